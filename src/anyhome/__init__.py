"""AnyHome: free-form text to a structured, furnished 3D house."""

from anyhome.errors import AnyHomeError
from anyhome.house import House, load
from anyhome.restyle import restyle as restyle

__version__ = "0.1.0"
__all__ = ["AnyHomeError", "House", "__version__", "generate", "load"]


def generate(text: str, seed: int = 0, **options) -> House:
    """Plan, lay out and furnish a house from text. See ``anyhome.pipeline.generate``."""
    from anyhome.pipeline import generate as _generate

    return _generate(text, seed=seed, **options)
