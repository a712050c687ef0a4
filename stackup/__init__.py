"""stackup: Monte Carlo tolerance stack-up and selective assembly of engine main bearings."""

__version__ = "0.1.0"
