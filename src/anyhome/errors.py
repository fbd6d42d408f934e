"""One exception family. Every error a user can cause or act on is an AnyHomeError.

The CLI prints ``str(error)`` on one line and exits non-zero; no traceback.
"""


class AnyHomeError(Exception):
    """Base class of every error AnyHome raises on purpose."""


class PlanError(AnyHomeError):
    """The text could not be turned into a house plan (empty, unusable...)."""


class FloorplanError(AnyHomeError):
    """The room program could not be laid out as a floorplan within the retry budget."""


class HouseFormatError(AnyHomeError):
    """A house.json is not of this format or version, or is malformed."""


class ExportError(AnyHomeError):
    """An output file (GLB, SVG...) could not be written."""


class EvalError(AnyHomeError):
    """Evaluation could not run (missing house, bad expectations file...)."""


class RenderError(AnyHomeError):
    """Images could not be rendered (renderer missing, no OpenGL context, bad camera...)."""


class LLMError(PlanError):
    """The LLM planner is misconfigured (bad base URL, bad config file, no openai client).

    A server that is down, slow or answers nonsense is *not* an error: the offline planner
    fills the stages it could not plan, with a warning."""


class KnowledgeError(AnyHomeError):
    """A knowledge file (shipped or a user's overlay) is unreadable or holds a bad entry.

    The message is one line: ``FILE: KEY: what is wrong``."""


class AssetLibraryError(AnyHomeError):
    """An asset library folder (``--assets DIR``) is missing, empty, or holds bad metadata
    or a model that cannot be loaded."""
