"""GLB export: the house's scene (:mod:`anyhome.scene`) as a binary glTF file.

The scene's root node ``house`` maps the plan frame (x east, y north, z up) to glTF's
+Y-up frame; each object node holds one child node per material part
(``object:<id>:<role>``); texture images are embedded once per distinct image.
"""

from __future__ import annotations

import os
from pathlib import Path

from anyhome.errors import ExportError
from anyhome.export.output import write_file
from anyhome.house import House
from anyhome.materials.gltf import embed_textures
from anyhome.sanitize import clean_text


def write_glb(house: House, path: str | os.PathLike[str], texture_px: int | None = None) -> Path:
    """Write the house as a binary glTF (GLB) file atomically; return its path.

    Texture images are encoded once per distinct image (base colour JPEG, maps PNG) and
    shared by every material that uses them.
    """
    # imported here: anyhome.scene imports anyhome.export.architecture (a cycle at import time)
    from anyhome.scene import one_line, scene_and_materials

    path = Path(path)
    try:
        scene, specs = scene_and_materials(house, texture_px, textures=False)
        data = embed_textures(scene.export(file_type="glb"), specs)
    except Exception as e:  # trimesh raises many kinds
        raise ExportError(f"could not build the GLB for {clean_text(path.name)}: {one_line(e)}") from e
    return write_file(path, data)
