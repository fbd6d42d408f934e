"""Material words that reach the GLB: does each material word of the plan show?

A house's material words are those of its surfaces' phrases (``room.materials``: floor,
walls, ceiling) and of its objects' ``material`` phrases, as the material catalog reads
them (the lexicon words of ``plan/knowledge/materials.yaml`` that have a texture kind,
the longest at each place: "white oak" before "oak"), plus its weathering words
(``weathering``: peeling, dusty, rusty...) and ceiling-structure words
(``ceiling_structure``: beams, coffered).

Each (surface, phrase, word) of the house is counted once, on the nodes of the written
GLB that carry it (``room:<id>:<part>``, and the parts ``object:<id>:<role>`` of every
object with that phrase; library models and surfaces the GLB has no node for are left
out). It is **realised** when, on every room surface that carries it, or on at least one
of the objects that carry it (a style's furniture words, "oak and matte black metal",
go to sofas that have no metal part and to lamps that do), on any of its parts:

- a texture word: a material of the texture kind and variant the catalog gives the word
  alone on that surface (``surface_material(word, surface)``: "walnut" on a floor is
  ``planks``, "damask" on walls ``wallpaper/damask``) is there (the material's name in the
  GLB is its key, :func:`anyhome.materials.images.material_key`);
- a weathering word: the surface's material is weathered (its key ends ``weathered``);
- a ceiling-structure word: the room has its ``room:<id>:beams`` / ``coffers`` node.

A word that loses to another of its clause ("oak and matte black metal" on a wall: the
wall is oak) or names a kind the surface turns into another is not realised; that is
what the figure is for (issue 15: at least 90 % realised).
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, cast

from anyhome.house import House
from anyhome.plan.kb import KnowledgeBase

ROOM_SURFACES = ("floor", "walls", "ceiling")


@dataclass
class MaterialWords:
    """The figure for one house: words counted, realised, and the misses."""

    n_words: int = 0
    n_realised: int = 0
    misses: list[str] = field(default_factory=list)  # "walls 'oak and brass': brass"
    by_kind: dict[str, list[int]] = field(default_factory=dict)  # texture | weathering | structure -> [realised, n]

    @property
    def share(self) -> float | None:
        return self.n_realised / self.n_words if self.n_words else None


def phrase_words(phrase: str, kb: KnowledgeBase | None = None) -> list[tuple[str, str]]:
    """(word, what) for each material word of ``phrase``: ``texture`` for the word that
    decides each clause (:func:`anyhome.materials.catalog.clause_heads`: in "warm oak
    linen" the material is linen, oak its colour), ``weathering`` and ``structure`` for
    those words; structure words first, in the phrase's order otherwise."""
    from anyhome.materials.catalog import _data, _words, clause_heads, find_structure

    weather = set(_data(kb).get("weathering") or ())
    out: list[tuple[str, str]] = []
    rest = phrase
    while (found := find_structure(rest, kb)) is not None:
        out.append((found[0], "structure"))
        rest = found[2]
    out += [(w, "texture") for w in clause_heads(rest, kb)]
    out += [(w, "weathering") for w in dict.fromkeys(_words(phrase)) if w in weather]
    return out


def _kind_of(key: str) -> tuple[str, str, bool]:
    """(kind, variant, weathered) of a GLB material named by its key."""
    head = key.split(" ", 1)[0]
    kind, _, variant = head.partition("/")
    return kind, variant, key.endswith(" weathered")


def glb_materials(path: str | Path) -> dict[str, list[str]]:
    """Node name -> the names of the materials of its meshes, read from a GLB file."""
    import trimesh

    scene = cast(trimesh.Scene, trimesh.load(str(path), force="scene"))
    out: dict[str, list[str]] = defaultdict(list)
    for node in scene.graph.nodes_geometry:
        _, geom = scene.graph[node]
        mesh = scene.geometry[geom]
        mat = getattr(getattr(mesh, "visual", None), "material", None)
        out[node].append(str(getattr(mat, "name", "") or ""))
    return dict(out)


def _realised(word: str, what: str, surface: str, keys: list[str], room_nodes: set[str], room_id: str | None,
              kb: KnowledgeBase | None) -> bool:
    from anyhome.materials.catalog import surface_material

    if what == "structure":
        return room_id is not None and any(f"room:{room_id}:{k}" in room_nodes for k in ("beams", "coffers"))
    if what == "weathering":
        return any(_kind_of(k)[2] for k in keys)
    spec = surface_material(word, surface, kb=kb)
    return any(_kind_of(k)[0] == spec.kind and (not spec.variant or _kind_of(k)[1] == spec.variant) for k in keys)


def material_words(house: House, glb: str | Path | dict[str, list[str]], kb: KnowledgeBase | None = None) -> MaterialWords:
    """The figure of the module doc for ``house`` and its GLB (a path, or the node ->
    material names of :func:`glb_materials`)."""
    nodes = glb if isinstance(glb, dict) else glb_materials(glb)
    names = set(nodes)
    # (surface, phrase) -> [(keys of one node or object, room id)]
    carriers: dict[tuple[str, str], list[tuple[list[str], str | None]]] = defaultdict(list)
    for room in house.rooms:
        for part in ROOM_SURFACES:
            phrase = room.materials.get(part, "")
            node = f"room:{room.id}:{part}"
            if phrase and node in nodes:
                carriers[(part, phrase)].append((nodes[node], room.id))
    by_object: dict[str, list[str]] = defaultdict(list)
    for node, keys in nodes.items():
        if node.startswith("object:"):
            by_object[node.split(":")[1]] += [k for k in keys if not k.startswith("library:")]
    for obj in house.objects:
        if obj.material and by_object.get(obj.id):
            carriers[("furniture", obj.material)].append((by_object[obj.id], None))
    rep = MaterialWords()
    for (surface, phrase), holders in sorted(carriers.items()):
        for word, what in phrase_words(phrase, kb):
            if what == "structure" and surface != "ceiling":
                continue
            shown = [_realised(word, what, surface, keys, names, rid, kb) for keys, rid in holders]
            ok = any(shown) if surface == "furniture" else all(shown)
            rep.n_words += 1
            rep.n_realised += ok
            tally = rep.by_kind.setdefault(what, [0, 0])
            tally[0] += ok
            tally[1] += 1
            if not ok:
                rep.misses.append(f"{surface} {phrase!r}: {word}")
    return rep


def summary(rep: MaterialWords) -> dict[str, Any]:
    """The figure as plain values (for ``anyhome eval --json`` and the benchmark)."""
    return {"n_material_words": rep.n_words, "n_material_words_realised": rep.n_realised,
            "material_words_realised": None if rep.share is None else round(rep.share, 4),
            "material_word_misses": rep.misses[:20]}
