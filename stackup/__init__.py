"""stackup: Monte Carlo tolerance stack-up and selective assembly of engine main bearings."""

__version__ = "0.1.0"

from . import design  # noqa: E402
from .plan import plan  # noqa: E402
from .rank import rank  # noqa: E402
from .study import Study  # noqa: E402
from .study.compare import Comparison, compare  # noqa: E402

__all__ = ["Comparison", "Study", "compare", "design", "plan", "rank", "__version__"]
