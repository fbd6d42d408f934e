"""The user's asset library (anyhome.assets.library): a folder of real model files built
here from trimesh primitives and procedural meshes, indexed, matched and rebuilt with
the real loading code."""

from __future__ import annotations

import json
import logging
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh
from procedural_helpers import fresh_mesh

from anyhome.assets import assign_asset, build_object_mesh
from anyhome.assets.library import (
    ASPECT_MAX_MISMATCH,
    CACHE_FILE,
    MATCH_MIN_SIMILARITY,
    Library,
    aspect_mismatch,
    best_matches,
    library_parts,
    library_record,
    open_library,
)
from anyhome.errors import AssetLibraryError, HouseFormatError
from anyhome.house import House, HouseObject

OBJECT_TO_GLTF = np.array([[-1.0, 0, 0, 0], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]])
"""Object frame (z up, front +y) -> a y-up file facing +z (glTF's convention); its own inverse."""
CHAIR_M = (0.45, 0.5, 0.9)
BATHTUB_M = (1.7, 0.75, 0.6)
BOOKCASE_M = (0.9, 0.35, 1.9)
WARDROBE_M = (1.0, 0.6, 2.0)


def _y_up(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    out = mesh.copy()
    out.apply_transform(OBJECT_TO_GLTF)
    return out


def build_library(folder: Path) -> Path:
    """wooden_chair.glb (y-up, meters), Bathtub.obj (y-up, centimeters, no metadata),
    bookcase.ply (z-up, metadata beside it), wardrobe.glb (a coloured box, metadata in
    index.json)."""
    folder.mkdir(parents=True, exist_ok=True)
    _y_up(fresh_mesh("chair", 1, CHAIR_M)).export(folder / "wooden_chair.glb")
    tub = _y_up(fresh_mesh("bathtub", 1, BATHTUB_M))
    tub.apply_scale(100.0)
    tub.export(folder / "Bathtub.obj")
    fresh_mesh("bookshelf", 1, BOOKCASE_M).export(folder / "bookcase.ply")
    (folder / "bookcase.yaml").write_text("up: z\nfront: +y\ncategory: bookshelf\ntags: [books, shelf]\n")
    box = trimesh.creation.box((WARDROBE_M[0], WARDROBE_M[2], WARDROBE_M[1]))  # y-up: height on y
    box.visual = trimesh.visual.TextureVisuals(
        material=trimesh.visual.material.PBRMaterial(baseColorFactor=[120, 80, 40, 255]))
    box.export(folder / "wardrobe.glb")
    (folder / "index.json").write_text(json.dumps({"wardrobe.glb": {"category": "wardrobe", "tags": ["closet"]}}))
    return folder


@pytest.fixture(scope="module")
def library_dir(tmp_path_factory) -> Path:
    return build_library(tmp_path_factory.mktemp("lib") / "models")


@pytest.fixture(scope="module")
def library(library_dir) -> Library:
    return open_library(library_dir)


def _model(lib: Library, path: str):
    return next(m for m in lib.models if m.path == path)


def _pick(lib: Library, name: str, category: str, size) -> str | None:
    match = best_matches(lib, [(name, category, size)])[0]
    return match.model.path if match else None


def test_index_names_units_and_up_axes(library):
    chair, tub = _model(library, "wooden_chair.glb"), _model(library, "Bathtub.obj")
    shelf, wardrobe = _model(library, "bookcase.ply"), _model(library, "wardrobe.glb")
    assert (chair.meta.name, tub.meta.name, wardrobe.meta.category) == ("wooden chair", "Bathtub", "wardrobe")
    assert shelf.meta.tags == ("books", "shelf") and shelf.meta.up == "z"
    assert tub.unit == "cm" and chair.unit == "m"  # a 170-unit bathtub is in centimeters
    for model, size in ((chair, CHAIR_M), (tub, BATHTUB_M), (shelf, BOOKCASE_M), (wardrobe, WARDROBE_M)):
        assert np.allclose(model.extents_m, size, atol=2e-3), (model.path, model.extents_m)


def test_threshold_separates_a_chair_from_a_bathtub(library_dir, tmp_path):
    only_chair = tmp_path / "chairs"
    only_chair.mkdir()
    (only_chair / "chair_wooden.glb").write_bytes((library_dir / "wooden_chair.glb").read_bytes())
    lib = open_library(only_chair)
    from anyhome.plan.embed import get_embedder

    emb = get_embedder(lib.embedder)
    chair, tub = emb.encode(["dining chair chair", "bathtub bathtub"]) @ lib.vectors[0]
    assert chair >= MATCH_MIN_SIMILARITY > tub
    assert _pick(lib, "dining chair", "chair", CHAIR_M) == "chair_wooden.glb"
    assert _pick(lib, "bathtub", "bathtub", BATHTUB_M) is None


def test_retrieval_by_words_and_aspect(library):
    assert _pick(library, "dining chair", "chair", (0.42, 0.49, 0.91)) == "wooden_chair.glb"
    assert _pick(library, "bathtub", "bathtub", (1.6, 0.8, 0.55)) == "Bathtub.obj"
    assert _pick(library, "bookcase", "bookshelf", (1.0, 0.3, 2.0)) == "bookcase.ply"
    assert _pick(library, "wardrobe", "wardrobe", (1.2, 0.6, 2.1)) == "wardrobe.glb"
    # a low, wide "wardrobe" box is not a wardrobe's shape: procedural instead
    assert aspect_mismatch(WARDROBE_M, (1.2, 0.4, 0.45)) > ASPECT_MAX_MISMATCH
    assert _pick(library, "wardrobe", "wardrobe", (1.2, 0.4, 0.45)) is None
    assert _pick(library, "rug", "rug", (2.0, 1.4, 0.01)) is None


def _chair(lib: Library, size=(0.6, 0.55, 1.0)) -> HouseObject:
    """A dining chair whose record names the library's chair model (its procedural fallback drawn as the stage does)."""
    obj = HouseObject(id="c1", room="living", name="dining chair", category="chair", position=(2, 2, 0), size=size)
    match = best_matches(lib, [(obj.name, obj.category, obj.size)])[0]
    assert match is not None
    obj.asset = library_record(lib, match, assign_asset(obj, np.random.default_rng(0), ""))
    return obj


def test_mesh_fills_the_box_bottom_centred_facing_plus_y(library):
    obj = _chair(library)
    mesh = build_object_mesh(obj)
    assert np.allclose(mesh.bounds, [[-0.3, -0.275, 0.0], [0.3, 0.275, 1.0]], atol=1e-6)
    # the back rest (the top fifth) stands at the back, -y, as in the procedural chair the file was made from
    source = fresh_mesh("chair", 1, CHAIR_M)
    for m in (mesh, source):
        v = np.asarray(m.vertices)
        top = v[v[:, 2] > 0.8 * v[:, 2].max()]
        assert top[:, 1].mean() < 0


def test_z_up_model_and_its_material_survive(library):
    rec = {"source": "library", "library": str(library.root), "path": "bookcase.ply",
           "sha256": _model(library, "bookcase.ply").sha256, "up": "z", "front": "+y", "unit": "m", "name": "bookcase"}
    parts = library_parts(rec, (1.0, 0.3, 2.0))
    assert parts is not None and np.allclose(trimesh.util.concatenate(parts).bounds, [[-0.5, -0.15, 0], [0.5, 0.15, 2.0]])
    rec = {**rec, "path": "wardrobe.glb", "sha256": _model(library, "wardrobe.glb").sha256, "up": "y", "front": "+z"}
    parts = library_parts(rec, WARDROBE_M)
    assert parts is not None
    color = parts[0].visual.material.baseColorFactor
    assert color[0] > color[1] > color[2]  # the model's own brown, not a procedural colour


def test_second_index_loads_nothing(tmp_path):
    lib_dir = build_library(tmp_path / "lib")
    first = open_library(lib_dir)
    assert sorted(first.loaded) == sorted(m.path for m in first.models)
    assert (lib_dir / CACHE_FILE).is_file()
    assert open_library(lib_dir).loaded == []
    # unchanged size and time: not even opened (garbage of the same size still indexes)
    chair = lib_dir / "wooden_chair.glb"
    st = chair.stat()
    good = chair.read_bytes()
    chair.write_bytes(b"\0" * len(good))
    os.utime(chair, ns=(st.st_atime_ns, st.st_mtime_ns))
    again = open_library(lib_dir)
    assert again.loaded == [] and _model(again, "wooden_chair.glb").sha256 == _model(first, "wooden_chair.glb").sha256
    # same bytes, new time: the hash matches, nothing is loaded
    chair.write_bytes(good)
    os.utime(chair, ns=(st.st_atime_ns, st.st_mtime_ns + 10**9))
    assert open_library(lib_dir).loaded == []
    # new content: loaded again
    _y_up(fresh_mesh("chair", 2, CHAIR_M)).export(chair)
    assert open_library(lib_dir).loaded == ["wooden_chair.glb"]


def test_changed_or_missing_file_falls_back_to_procedural(tmp_path, caplog):
    lib = open_library(build_library(tmp_path / "lib"))
    obj = _chair(lib)
    expected = build_object_mesh(obj.model_copy(update={"asset": obj.asset["fallback"]}))
    path = lib.root / "wooden_chair.glb"
    path.write_bytes(path.read_bytes() + b"    ")
    with caplog.at_level(logging.WARNING, logger="anyhome.assets.library"):
        mesh = build_object_mesh(obj)
    assert "sha256 differs" in caplog.text
    assert np.array_equal(mesh.vertices, expected.vertices)
    path.unlink()
    assert np.array_equal(build_object_mesh(obj).vertices, expected.vertices)


def test_bad_folders_and_metadata(tmp_path):
    with pytest.raises(AssetLibraryError, match="not a folder"):
        open_library(tmp_path / "nope")
    (tmp_path / "empty").mkdir()
    (tmp_path / "empty" / "notes.txt").write_text("hi")
    with pytest.raises(AssetLibraryError, match="holds no model files"):
        open_library(tmp_path / "empty")
    lib = build_library(tmp_path / "lib")
    (lib / "bookcase.yaml").write_text("up: x\n")
    with pytest.raises(AssetLibraryError, match="bookcase.yaml: up: must be y or z"):
        open_library(lib)
    (lib / "bookcase.yaml").write_text("up: z\ncolour: red\n")
    with pytest.raises(AssetLibraryError, match="unknown keys colour"):
        open_library(lib)


def test_house_json_accepts_library_records_and_checks_them(library):
    from two_rooms import two_room_house

    obj = _chair(library)
    text = two_room_house([obj]).to_json()
    assert House.from_json(text).objects[0].asset == obj.asset
    data = json.loads(text)
    data["objects"][0]["asset"]["sha256"] = "xyz"
    with pytest.raises(HouseFormatError, match="sha256"):
        House.from_json(json.dumps(data))
    data["objects"][0]["asset"]["sha256"] = obj.asset["sha256"]
    data["objects"][0]["asset"]["fallback"]["params"]["knobs"] = {}
    with pytest.raises(HouseFormatError, match="fallback.params.knobs"):
        House.from_json(json.dumps(data))


def _anyhome(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "anyhome", *args], capture_output=True, text=True, timeout=180)


def test_cli_generate_with_a_library(tmp_path):
    lib = build_library(tmp_path / "my models")
    out = tmp_path / "out"
    proc = _anyhome("generate", "a dining room with a table and four chairs", "--assets", str(lib),
                    "--out", str(out), "-q")
    assert proc.returncode == 0, proc.stderr
    house = json.loads((out / "house.json").read_text())
    chairs = [o for o in house["objects"] if o["category"] == "chair"]
    assert len(chairs) == 4
    assert all(o["asset"]["source"] == "library" and o["asset"]["path"] == "wooden_chair.glb" for o in chairs)
    tables = [o for o in house["objects"] if "table" in o["name"]]
    assert tables and all(o["asset"]["source"] == "procedural" for o in tables)
    report = _anyhome("eval", str(out), "--json")
    assert report.returncode == 0, report.stderr
    assert json.loads(report.stdout)["violations"] == []
    # the reloaded house rebuilds the meshes the GLB holds
    from anyhome.house import load

    reloaded = load(out)
    scene = trimesh.load(out / "house.glb", force="scene")
    for obj in (o for o in reloaded.objects if o.category == "chair"):
        node = f"object:{obj.id}:model"
        geom = scene.geometry[scene.graph[node][1]]
        mesh = build_object_mesh(obj)
        assert len(geom.vertices) == len(mesh.vertices)
        assert np.allclose(geom.bounds, mesh.bounds, atol=1e-5)
        assert np.allclose(mesh.extents, obj.size, atol=1e-6)
        assert geom.visual.kind == "vertex"  # the model's own vertex colours
    listed = _anyhome("assets", "--library", str(lib), "--json")
    assert listed.returncode == 0, listed.stderr
    assert {r["path"]: r["unit"] for r in json.loads(listed.stdout)}["Bathtub.obj"] == "cm"


def test_cli_missing_library_is_one_line(tmp_path):
    proc = _anyhome("generate", "a bedroom", "--assets", str(tmp_path / "missing"), "--out", str(tmp_path / "o"))
    assert proc.returncode == 2
    assert proc.stderr.strip().count("\n") == 0 and "is not a folder" in proc.stderr
    assert not (tmp_path / "o").exists()
    env = {**os.environ, "ANYHOME_ASSETS": str(tmp_path)}
    proc = subprocess.run([sys.executable, "-m", "anyhome", "generate", "a bedroom", "--out", str(tmp_path / "o")],
                          capture_output=True, text=True, timeout=180, env=env)
    assert proc.returncode == 2 and "holds no model files" in proc.stderr


def test_glb_embeds_the_model_with_its_material(library, tmp_path):
    from two_rooms import two_room_house

    from anyhome.export.glb import write_glb
    from anyhome.materials.gltf import read_glb

    wardrobe = HouseObject(id="w1", room="bed", name="wardrobe", category="wardrobe", position=(7.0, 2.0, 0),
                           size=(1.1, 0.6, 2.0))
    match = best_matches(library, [(wardrobe.name, wardrobe.category, wardrobe.size)])[0]
    assert match is not None and match.model.path == "wardrobe.glb"
    wardrobe.asset = library_record(library, match, assign_asset(wardrobe, np.random.default_rng(0), ""))
    tree, _ = read_glb(write_glb(two_room_house([wardrobe]), tmp_path / "house.glb").read_bytes())
    node = next(n for n in tree["nodes"] if n.get("name") == "object:w1:model")
    material = tree["materials"][tree["meshes"][node["mesh"]]["primitives"][0]["material"]]
    assert material["name"] == "library:w1:1"
    # the file's linear factor comes back as it was (sRGB in the scene, linear in the file)
    assert np.allclose(material["pbrMetallicRoughness"]["baseColorFactor"], [120 / 255, 80 / 255, 40 / 255, 1.0], atol=0.01)


def test_restyle_keeps_the_library_model(library):
    from two_rooms import two_room_house

    from anyhome.restyle import restyle

    obj = _chair(library)
    styled = restyle(two_room_house([obj]), "gothic").objects[0]
    assert styled.asset is not None and styled.asset["path"] == "wooden_chair.glb"
    assert styled.asset["fallback"]["params"]["style"] == "gothic"
