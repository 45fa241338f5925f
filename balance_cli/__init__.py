"""balance: compare reciprocating-engine layouts for mechanical balance."""

__version__ = "0.1.0"

from .compare import EngineResult, analyse  # noqa: E402
from .config import ConfigError, load, load_many  # noqa: E402
from .firing import Firing, FiringError, firing, tdc_angles  # noqa: E402
from .model import Cylinder, Engine, ModelError, Throw  # noqa: E402
from .shaking import OrderComponents, Shaking, shaking  # noqa: E402

__all__ = [
    "ConfigError", "Cylinder", "Engine", "EngineResult", "Firing", "FiringError", "ModelError",
    "OrderComponents", "Shaking", "Throw", "analyse", "firing", "load", "load_many", "shaking",
    "tdc_angles",
]
