"""The OpenGL context: moderngl on a headless EGL display (Mesa's software llvmpipe
on a machine without a GPU). moderngl is an optional dependency, imported here only.
"""

from __future__ import annotations

import logging
from typing import Any

from anyhome.errors import RenderError

log = logging.getLogger(__name__)

GL_VERSION = 330
"""OpenGL version the shaders need (``#version 330 core``)."""
INSTALL_HINT = "pip install 'anyhome[render]'"
EGL_HINT = "install Mesa's EGL (Debian/Ubuntu: apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri)"


def import_moderngl() -> Any:
    """The moderngl module, or a RenderError saying how to install it."""
    try:
        import moderngl
    except ImportError:
        raise RenderError(f"rendering needs moderngl: {INSTALL_HINT}") from None
    return moderngl


def create_context() -> Any:
    """A standalone (windowless) moderngl context on EGL.

    Raises
    ------
    RenderError
        if moderngl is not installed or no EGL display can be opened.
    """
    moderngl = import_moderngl()
    try:
        ctx = moderngl.create_standalone_context(require=GL_VERSION, backend="egl")
    except Exception as e:  # glcontext raises plain Exceptions
        first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        raise RenderError(f"no headless OpenGL {GL_VERSION // 100}.{GL_VERSION % 100 // 10} "
                          f"context on EGL ({first}); {EGL_HINT}") from None
    log.debug("OpenGL context: %s, %s", ctx.info.get("GL_RENDERER"), ctx.info.get("GL_VERSION"))
    return ctx
