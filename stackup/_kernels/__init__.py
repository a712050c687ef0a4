"""numba kernels of the hot loops, called only through the public API.

Each kernel has a plain-Python/numpy twin in the tests that it must match.
"""
