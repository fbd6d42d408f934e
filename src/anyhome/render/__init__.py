"""Headless renders of a house: a bird's-eye image and one eye-level view per room,
with optional depth and instance maps for embodied-AI use.

Rendering uses OpenGL 3.3 through moderngl on an EGL context, which works without a
display or GPU (Mesa's llvmpipe). moderngl is optional: ``pip install 'anyhome[render]'``.
"""

from anyhome.render.api import render_house
from anyhome.render.cameras import Camera, birdseye_camera, room_camera
from anyhome.render.renderer import Frame, Renderer

__all__ = ["Camera", "Frame", "Renderer", "birdseye_camera", "render_house", "room_camera"]
