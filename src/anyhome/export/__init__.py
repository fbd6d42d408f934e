"""Outputs derived from house.json: GLB (glTF, +Y up) and a floorplan SVG."""

from anyhome.export.glb import write_glb
from anyhome.export.svg import write_svg

__all__ = ["write_glb", "write_svg"]
