"""A user's asset library: a folder of GLB/GLTF/OBJ/PLY models used instead of the
procedural families for the objects whose names they match (``--assets DIR``).

The folder format is documented in docs/asset_library.md. In short: every model file
under the folder (subfolders too) is a model; its metadata (name, category, tags, style,
up axis, front axis, unit) comes from ``<model>.json`` / ``<model>.yaml`` beside it or
from an ``index.json`` / ``index.yaml`` at the top, and defaults to the file's stem as
the name, y up, front +z (glTF's convention; -y for z-up files, Blender's) and meters
(or a guess from an absurd size).

:func:`open_library` indexes the folder once: each model's bounding box in its own file
frame (loading the file) and the embedding of its words (the planner's embedder,
:func:`anyhome.plan.embed.get_embedder`). The index is cached in
``DIR/.anyhome-index.json`` (or the user cache folder if DIR is read-only), keyed by
file path, size, modification time and content hash, so a second run loads no unchanged
file. :func:`best_match` picks a model for an object by text similarity and the fit of
its aspect to the object's box; :func:`library_record` is the record house.json keeps
(the file, its hash, its normalisation) and :func:`library_parts` rebuilds the meshes
from the record alone: up axis and front normalised, bottom-centred, each axis scaled
to the object's box exactly (the mesh fills the box, as procedural ones do).
"""

from __future__ import annotations

import hashlib
import json
import logging
import os
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np
import trimesh

from anyhome.errors import AssetLibraryError
from anyhome.sanitize import clean_text

log = logging.getLogger(__name__)

SOURCE = "library"
"""``source`` of an asset record that names a library file."""
ENV_ASSETS = "ANYHOME_ASSETS"
"""Environment variable naming the asset library folder (``--assets`` wins over it)."""
CONFIG_TABLE = "assets"
"""Config-file table whose ``dir`` key names the library folder (after ``--assets`` and the environment)."""
MODEL_SUFFIXES = (".glb", ".gltf", ".obj", ".ply")
"""File types read as models."""
METADATA_SUFFIXES = (".json", ".yaml", ".yml")
"""Metadata beside a model: ``<stem><suffix>``."""
INDEX_FILES = ("index.json", "index.yaml", "index.yml")
"""One metadata file for the whole folder (a per-model file beside a model wins over it)."""
CACHE_FILE = ".anyhome-index.json"
"""The cached index inside the library folder."""
CACHE_VERSION = 1
"""Bumped when the cached entries change meaning."""
UNIT_SCALES_M = {"m": 1.0, "cm": 0.01, "mm": 0.001}
"""Meters per file unit."""
UNIT_GUESS_MAX_M = 20.0
"""A model without a unit whose largest side is over this many 'meters' is not in meters."""
UNIT_GUESS_CM_MAX = 500.0
"""... and is in centimeters up to this largest side (a 5 m piece), else in millimeters."""
AXES: dict[str, tuple[float, float, float]] = {
    "+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1), "-z": (0, 0, -1),
}  # fmt: skip
DEFAULT_FRONT = {"y": "+z", "z": "-y"}
"""The front of a model by its up axis: glTF's +Z for y-up files, Blender's -Y for z-up."""
MATCH_MIN_SIMILARITY = 0.6
"""Least cosine similarity of an object's words to a model's for the model to be used
(hybrid embedder, tests/assets/test_library.py: "dining chair" ~ the file name "wooden
chair" 0.67, "bathtub" ~ it 0.25, "office chair" ~ it 0.51, "sofa" ~ it 0.38)."""
ASPECT_WEIGHT = 0.3
"""Similarity given up per unit of aspect mismatch (:func:`aspect_mismatch`) in the ranking."""
ASPECT_MAX_MISMATCH = 0.45
"""A model whose aspect is further than this from the box is not used (a wardrobe for a bench: 0.6)."""
MIN_EXTENT_M = 1e-4
"""A flat side of a model (a rug, a picture) counts as this thick when comparing aspects."""


# ------------------------------------------------------------------ metadata
@dataclass(frozen=True)
class Meta:
    """What a model is and how its file is oriented (see the module doc)."""

    name: str
    category: str = ""
    tags: tuple[str, ...] = ()
    style: str = ""
    up: str = "y"
    front: str = ""
    unit: str = ""

    def text(self) -> str:
        """The words embedded for retrieval: name, category and tags."""
        return " ".join(w for w in (self.name, self.category, *self.tags) if w)

    def front_axis(self) -> str:
        return self.front or DEFAULT_FRONT[self.up]


_META_KEYS = frozenset({"name", "category", "tags", "style", "up", "front", "unit", "file"})


def default_name(path: Path) -> str:
    """A model's name from its file name: the stem with ``_`` and ``-`` as spaces."""
    return " ".join(path.stem.replace("_", " ").replace("-", " ").split())


def _read_mapping(path: Path) -> Any:
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise AssetLibraryError(f"{path}: cannot read: {getattr(e, 'strerror', None) or e}") from None
    try:
        if path.suffix == ".json":
            return json.loads(text)
        import yaml

        return yaml.safe_load(text)
    except Exception as e:  # json and yaml raise their own kinds
        raise AssetLibraryError(f"{path}: not valid {path.suffix[1:].upper()}: {clean_text(str(e)).splitlines()[0]}") from None


def _word(raw: Any, where: str, key: str) -> str:
    if not isinstance(raw, str):
        raise AssetLibraryError(f"{where}: {key}: must be a string")
    return " ".join(raw.split())


def parse_meta(raw: Any, path: Path, where: str) -> Meta:
    """The metadata of the model at ``path`` from a mapping read from ``where``."""
    if raw is None:
        raw = {}
    if not isinstance(raw, Mapping):
        raise AssetLibraryError(f"{where}: must be a mapping of name, category, tags, style, up, front, unit")
    unknown = sorted(set(map(str, raw)) - _META_KEYS)
    if unknown:
        raise AssetLibraryError(f"{where}: unknown keys {clean_text(', '.join(unknown))[:120]}")
    tags = raw.get("tags", [])
    if isinstance(tags, str):
        tags = [t for t in tags.split(",")]
    if not isinstance(tags, list):
        raise AssetLibraryError(f"{where}: tags: must be a list of words")
    up = str(raw.get("up", "y")).lower().lstrip("+")
    if up not in DEFAULT_FRONT:
        raise AssetLibraryError(f"{where}: up: must be y or z")
    unit = str(raw.get("unit", "")).lower()
    if unit and unit not in UNIT_SCALES_M:
        raise AssetLibraryError(f"{where}: unit: must be one of {', '.join(UNIT_SCALES_M)}")
    front = str(raw.get("front", "")).lower()
    front = front if not front or front[0] in "+-" else f"+{front}"
    if front and (front not in AXES or front[1] == up):
        raise AssetLibraryError(f"{where}: front: must be an axis across the up axis, like +z, -y, +x")
    meta = Meta(name=_word(raw.get("name", default_name(path)), where, "name") or default_name(path),
                category=_word(raw.get("category", ""), where, "category"),
                tags=tuple(_word(t, where, "tags") for t in tags if str(t).strip()),
                style=_word(raw.get("style", ""), where, "style"), up=up, front=front, unit=unit)
    return meta


def _index_metadata(root: Path) -> dict[str, Any]:
    """The top-level index file's entries by model path (relative, posix); {} without one."""
    for name in INDEX_FILES:
        path = root / name
        if not path.is_file():
            continue
        raw = _read_mapping(path)
        if isinstance(raw, Mapping) and isinstance(raw.get("models"), (list, Mapping)):
            raw = raw["models"]
        if isinstance(raw, Mapping):
            return {str(k): v for k, v in raw.items()}
        if isinstance(raw, list) and all(isinstance(e, Mapping) and isinstance(e.get("file"), str) for e in raw):
            return {str(e["file"]): e for e in raw}
        raise AssetLibraryError(f"{path}: must map model files to their metadata (or list entries with 'file')")
    return {}


def model_meta(root: Path, rel: str, index: Mapping[str, Any]) -> Meta:
    """A model's metadata: the file beside it, else its index entry, else the defaults."""
    path = root / rel
    for suffix in METADATA_SUFFIXES:
        side = path.with_suffix(suffix)
        if side.is_file():
            return parse_meta(_read_mapping(side), path, str(side))
    return parse_meta(index.get(rel), path, f"{root / INDEX_FILES[0]}: {rel}" if rel in index else str(path))


# --------------------------------------------------------------- geometry
def load_parts(path: Path) -> list[trimesh.Trimesh]:
    """The model's meshes in its own file frame, each with its own visual (colours,
    material); scene graph transforms applied. Raises AssetLibraryError on a file
    trimesh cannot read or that holds no triangles."""
    try:
        scene = trimesh.load(str(path), force="scene")
        dumped = scene.dump(concatenate=False) if isinstance(scene, trimesh.Scene) else [scene]
        parts = [g for g in dumped if isinstance(g, trimesh.Trimesh) and len(g.faces)]
    except Exception as e:  # trimesh raises many kinds
        raise AssetLibraryError(f"{path}: cannot load the model: {clean_text(str(e)).splitlines()[0][:200] if str(e) else type(e).__name__}") from None
    if not parts:
        raise AssetLibraryError(f"{path}: the model holds no triangles")
    return parts


def rotation(up: str, front: str) -> np.ndarray:
    """3x3 rotation taking file coordinates to the object frame (z up, front +y): the
    object's x is front x up, y the front, z the up axis (a proper rotation: no mirror)."""
    u = np.array(AXES[f"+{up}"], dtype=float)
    f = np.array(AXES[front], dtype=float)
    return np.array([np.cross(f, u), f, u])


def unit_scale(meta: Meta, largest_extent: float) -> tuple[str, float]:
    """(unit, meters per file unit): the metadata's unit, else meters unless the model
    would be over :data:`UNIT_GUESS_MAX_M` long (then centimeters or millimeters)."""
    unit = meta.unit
    if not unit:
        unit = "m" if largest_extent <= UNIT_GUESS_MAX_M else "cm" if largest_extent <= UNIT_GUESS_CM_MAX else "mm"
    return unit, UNIT_SCALES_M[unit]


def normalised_extents(raw_bounds: np.ndarray, meta: Meta) -> tuple[str, np.ndarray]:
    """(unit, the model's box in meters in the object frame) from its file-frame bounds."""
    ext = np.abs(rotation(meta.up, meta.front_axis()) @ (raw_bounds[1] - raw_bounds[0]))
    unit, scale = unit_scale(meta, float(ext.max()))
    return unit, ext * scale


def fitted_parts(parts: Sequence[trimesh.Trimesh], up: str, front: str,
                 size: Sequence[float]) -> list[trimesh.Trimesh]:
    """Copies of ``parts`` turned into the object frame, bottom-centred and scaled on each
    axis to fill ``size`` (width, depth, height in meters) exactly."""
    rot = rotation(up, front)
    out = [p.copy() for p in parts]
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    for p in out:
        p.vertices = np.asarray(p.vertices, dtype=float) @ rot.T
        lo, hi = np.minimum(lo, p.vertices.min(axis=0)), np.maximum(hi, p.vertices.max(axis=0))
    ext = np.maximum(hi - lo, MIN_EXTENT_M)
    scale = np.asarray(size, dtype=float) / ext
    centre = np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]])
    for p in out:
        p.vertices = (np.asarray(p.vertices) - centre) * scale
    return out


def file_sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


# ------------------------------------------------------------------ index
@dataclass(frozen=True)
class Model:
    """One indexed model: its file, metadata and box."""

    path: str
    """Relative to the library folder, with ``/``."""
    sha256: str
    meta: Meta
    unit: str
    extents_m: tuple[float, float, float]
    """Width, depth, height in meters in the object frame."""


@dataclass
class Library:
    """An indexed asset library folder."""

    root: Path
    """The folder, resolved."""
    models: list[Model]
    vectors: np.ndarray
    """One unit row per model: the embedding of its words."""
    embedder: str
    cache_path: Path | None = None
    loaded: list[str] = field(default_factory=list)
    """The model files this indexing loaded (not taken from the cache)."""


def check_folder(folder: str | os.PathLike[str]) -> Path:
    """The library folder resolved; one-line AssetLibraryError when it is missing or empty."""
    root = Path(folder).expanduser()
    if not root.is_dir():
        raise AssetLibraryError(f"asset library {clean_text(str(folder))} is not a folder")
    if not model_files(root.resolve()):
        raise AssetLibraryError(f"asset library {clean_text(str(folder))} holds no model files "
                                f"({', '.join(s[1:] for s in MODEL_SUFFIXES)})")
    return root.resolve()


def model_files(root: Path) -> list[str]:
    """Every model file under ``root``, relative and sorted, skipping hidden folders."""
    out = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if not d.startswith("."))
        for name in filenames:
            if name.lower().endswith(MODEL_SUFFIXES) and not name.startswith("."):
                out.append((Path(dirpath) / name).relative_to(root).as_posix())
    return sorted(out)


def user_cache_dir() -> Path:
    """Where the index of a read-only library folder goes."""
    return Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "anyhome" / "assets"


def _cache_candidates(root: Path) -> list[Path]:
    key = hashlib.sha256(str(root).encode("utf-8", "surrogateescape")).hexdigest()[:16]
    return [root / CACHE_FILE, user_cache_dir() / f"{key}.json"]


def _read_cache(paths: Sequence[Path]) -> dict[str, Any]:
    for path in paths:
        try:
            data = json.loads(path.read_bytes())
        except (OSError, ValueError):
            continue
        if isinstance(data, dict) and data.get("version") == CACHE_VERSION and isinstance(data.get("files"), dict):
            return data["files"]
    return {}


def _write_cache(paths: Sequence[Path], files: dict[str, Any]) -> Path | None:
    """Write the index to the first of ``paths`` that takes it (atomically); None if none does."""
    from anyhome.outdir import atomic_write_bytes

    data = json.dumps({"version": CACHE_VERSION, "files": files}, separators=(",", ":")).encode("utf-8")
    for path in paths:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            atomic_write_bytes(path, data)
            return path
        except OSError as e:
            log.debug("could not write the asset index %s: %s", path, e)
    return None


def _file_entry(root: Path, rel: str, cached: Mapping[str, Any], by_hash: Mapping[str, Any],
                loaded: list[str]) -> dict[str, Any]:
    """The cache entry of one file: taken over when its size and time (or, failing
    those, its content hash) are unchanged, else made by loading the file."""
    path = root / rel
    st = path.stat()
    old = cached.get(rel)
    if isinstance(old, dict) and old.get("size") == st.st_size and old.get("mtime_ns") == st.st_mtime_ns:
        return old
    digest = file_sha256(path)
    same = by_hash.get(digest)
    if same is not None:
        return {**same, "size": st.st_size, "mtime_ns": st.st_mtime_ns}
    parts = load_parts(path)
    loaded.append(rel)
    lo = np.min([p.bounds[0] for p in parts], axis=0)
    hi = np.max([p.bounds[1] for p in parts], axis=0)
    return {"size": st.st_size, "mtime_ns": st.st_mtime_ns, "sha256": digest,
            "bounds": [[float(x) for x in lo], [float(x) for x in hi]], "vectors": {}}


def _valid_entry(e: Any) -> bool:
    try:
        return (isinstance(e["sha256"], str) and np.asarray(e["bounds"], dtype=float).shape == (2, 3)
                and isinstance(e["vectors"], dict))
    except (KeyError, TypeError, ValueError):
        return False


def open_library(folder: str | os.PathLike[str], embedder: str | None = None) -> Library:
    """Index the library folder (see the module doc); raises AssetLibraryError on a
    missing or empty folder, bad metadata or a model that cannot be loaded."""
    from anyhome.plan.embed import get_embedder

    root = check_folder(folder)
    emb = get_embedder(embedder)
    candidates = _cache_candidates(root)
    cached = {k: v for k, v in _read_cache(candidates).items() if _valid_entry(v)}
    by_hash = {v["sha256"]: v for v in cached.values()}
    index = _index_metadata(root)
    files: dict[str, Any] = {}
    models: list[Model] = []
    loaded: list[str] = []
    for rel in model_files(root):
        entry = _file_entry(root, rel, cached, by_hash, loaded)
        files[rel] = entry
        meta = model_meta(root, rel, index)
        unit, ext = normalised_extents(np.asarray(entry["bounds"], dtype=float), meta)
        models.append(Model(rel, entry["sha256"], meta, unit, (float(ext[0]), float(ext[1]), float(ext[2]))))
    vectors = _vectors(models, files, emb)
    changed = any(files[k] is not cached.get(k) for k in files) or set(files) != set(cached)
    path = _write_cache(candidates, files) if changed else next((p for p in candidates if p.is_file()), None)
    log.debug("asset library %s: %d models, %d loaded", root, len(models), len(loaded))
    return Library(root, models, vectors, emb.name, path, loaded)


def _vectors(models: Sequence[Model], files: dict[str, Any], emb: Any) -> np.ndarray:
    """Each model's embedding, from its cache entry when the words and embedder match."""
    texts = [m.meta.text() for m in models]
    rows: list[np.ndarray | None] = []
    for m, text in zip(models, texts):
        got = files[m.path]["vectors"].get(emb.name)
        ok = isinstance(got, dict) and got.get("text") == text and isinstance(got.get("v"), list)
        rows.append(np.asarray(got["v"], dtype=np.float32) if ok else None)
    todo = [i for i, r in enumerate(rows) if r is None]
    if todo:
        fresh = emb.encode([texts[i] for i in todo])
        for i, v in zip(todo, fresh):
            rows[i] = v
            entry = files[models[i].path] = {**files[models[i].path]}
            entry["vectors"] = {**entry["vectors"], emb.name: {"text": texts[i], "v": [round(float(x), 6) for x in v]}}
    return np.vstack([r for r in rows if r is not None]) if rows else np.zeros((0, 1), dtype=np.float32)


# -------------------------------------------------------------- retrieval
def object_text(name: str, category: str) -> str:
    """The words of an object compared with the models' words."""
    return " ".join(f"{name} {category}".replace("_", " ").split())


def aspect_mismatch(extents_m: Sequence[float], size_m: Sequence[float]) -> float:
    """How far a model's proportions are from the box's, scale aside: the mean absolute
    deviation of the per-axis log size ratios from their mean (0: same proportions;
    a 2 m wardrobe for a 0.45 m high bench: about 0.6)."""
    a = np.log(np.maximum(np.asarray(extents_m, dtype=float), MIN_EXTENT_M))
    b = np.log(np.maximum(np.asarray(size_m, dtype=float), MIN_EXTENT_M))
    d = a - b
    return float(np.mean(np.abs(d - d.mean())))


@dataclass(frozen=True)
class Match:
    model: Model
    similarity: float
    mismatch: float


def best_matches(library: Library, objects: Sequence[tuple[str, str, Sequence[float]]]) -> list[Match | None]:
    """For each (name, category, size) the best model: among those at least
    :data:`MATCH_MIN_SIMILARITY` similar in words and at most :data:`ASPECT_MAX_MISMATCH`
    off in aspect, the highest similarity less :data:`ASPECT_WEIGHT` times the mismatch;
    None where no model qualifies."""
    from anyhome.plan.embed import get_embedder

    if not objects or not library.models:
        return [None] * len(objects)
    emb = get_embedder(library.embedder)
    sims = emb.encode([object_text(n, c) for n, c, _ in objects]) @ library.vectors.T
    out: list[Match | None] = []
    for (_, _, size), row in zip(objects, sims):
        best: Match | None = None
        for j in np.flatnonzero(row >= MATCH_MIN_SIMILARITY):
            model = library.models[int(j)]
            mis = aspect_mismatch(model.extents_m, size)
            if mis > ASPECT_MAX_MISMATCH:
                continue
            if best is None or row[j] - ASPECT_WEIGHT * mis > best.similarity - ASPECT_WEIGHT * best.mismatch:
                best = Match(model, float(row[j]), mis)
        out.append(best)
    return out


def library_record(library: Library, match: Match, fallback: dict[str, Any]) -> dict[str, Any]:
    """The asset record of an object built from a library model (see docs/house_format.md):
    the library folder (absolute, so the house reloads from any working folder), the
    file relative to it, its hash and normalisation; ``fallback`` is the procedural
    record built when the file is gone or changed."""
    m = match.model
    return {"source": SOURCE, "library": str(library.root), "path": m.path, "sha256": m.sha256, "name": m.meta.name,
            "up": m.meta.up, "front": m.meta.front_axis(), "unit": m.unit,
            "similarity": round(match.similarity, 4), "family": fallback.get("family", ""),
            "fallback": fallback}


# ------------------------------------------------------------- rebuilding
def record_file(record: Mapping[str, Any]) -> Path:
    """The model file a library record names (its path, under its library folder when relative)."""
    path = Path(str(record["path"]))
    return path if path.is_absolute() else Path(str(record.get("library", ""))).expanduser() / path


@lru_cache(maxsize=64)
def _checked_parts(path: str, sha256: str) -> tuple[trimesh.Trimesh, ...]:
    """The parts of the file at ``path`` if its content hash is ``sha256``."""
    p = Path(path)
    if not p.is_file():
        raise AssetLibraryError(f"{path}: the model file is missing")
    if file_sha256(p) != sha256:
        raise AssetLibraryError(f"{path}: the model file changed since the house was made (sha256 differs)")
    return tuple(srgb_factors(m) for m in load_parts(p))


def srgb_factors(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """``mesh`` with a PBR base colour factor read from a file (linear, as glTF defines
    it) turned to the sRGB values AnyHome's scene holds (the GLB writer turns them back,
    see :func:`anyhome.materials.gltf.linear_factors`)."""
    mat = getattr(mesh.visual, "material", None)
    factor = getattr(mat, "baseColorFactor", None)
    if factor is not None and mat is not None:
        c = np.asarray(factor, dtype=float) / 255.0
        rgb = np.where(c[:3] <= 0.0031308, c[:3] * 12.92, 1.055 * np.power(c[:3], 1 / 2.4) - 0.055)
        mat.baseColorFactor = np.round(np.append(rgb, c[3:4]) * 255).astype(np.uint8)
    return mesh


def library_parts(record: Mapping[str, Any], size: Sequence[float]) -> list[trimesh.Trimesh] | None:
    """The meshes of a library record fitted to ``size`` in the object frame, each with
    the model's own visual; None (and a logged warning) when the file is missing,
    changed or unreadable: the caller builds the fallback."""
    try:
        parts = _checked_parts(str(record_file(record)), str(record["sha256"]))
        up = str(record.get("up", "y"))
        return fitted_parts(parts, up, str(record.get("front") or DEFAULT_FRONT[up]), size)
    except (AssetLibraryError, KeyError, OSError) as e:
        log.warning("asset %s: %s; using the procedural fallback", clean_text(str(record.get("path", "?"))), clean_text(str(e)))
        return None


def library_mesh(record: Mapping[str, Any], size: Sequence[float]) -> trimesh.Trimesh | None:
    """:func:`library_parts` as one mesh (the parts' geometry joined), or None."""
    parts = library_parts(record, size)
    if parts is None:
        return None
    if len(parts) == 1:
        return parts[0]
    joined = trimesh.util.concatenate(parts)
    return joined if isinstance(joined, trimesh.Trimesh) else None


# ---------------------------------------------------------------- the stage
def folder_in_force(cli: str | None, config_file: str | os.PathLike[str] | None = None) -> str | None:
    """The library folder to use: ``--assets``, else :data:`ENV_ASSETS`, else the config
    file's ``[assets] dir``; None: no library."""
    if cli:
        return cli
    if os.environ.get(ENV_ASSETS):
        return os.environ[ENV_ASSETS]
    return _config_dir(config_file)


def _config_dir(config_file: str | os.PathLike[str] | None) -> str | None:
    from anyhome.plan.llm.config import CONFIG_ENV, default_config_file

    named = config_file or os.environ.get(CONFIG_ENV)
    path = Path(named) if named else default_config_file()
    if not path.is_file():
        return None
    try:
        import tomllib  # type: ignore[import-not-found, unused-ignore]  # standard library from 3.11 on

        data = tomllib.loads(path.read_bytes().decode("utf-8"))
    except Exception as e:  # unreadable, not UTF-8, not TOML
        if not named:  # the default file only matters to the run that uses it (the LLM planner reports it)
            log.debug("config file %s unreadable: %s", path, e)
            return None
        raise AssetLibraryError(f"config file {path}: cannot read [{CONFIG_TABLE}]: {clean_text(str(e))[:200]}") from None
    table = data.get(CONFIG_TABLE, {})
    value = table.get("dir") if isinstance(table, dict) else None
    if value is not None and not isinstance(value, str):
        raise AssetLibraryError(f"config file {path}: [{CONFIG_TABLE}] dir must be a string")
    return value or None
