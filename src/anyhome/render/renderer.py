"""The OpenGL renderer: uploads a house's batches once, then renders cameras to a
colour image (supersampled, lit, tone-mapped, sRGB) and optionally to depth and instance
maps. Each batch draws with its base colour, metallicRoughness and normal textures
(1 x 1 neutral ones stand in for those it lacks).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from anyhome.errors import RenderError
from anyhome.render import shaders
from anyhome.render.cameras import Camera
from anyhome.render.gl import create_context, import_moderngl
from anyhome.render.lights import (
    EMISSIVE_STRENGTH,
    EXPOSURE,
    GROUND_BOUNCE_RGB,
    INDOOR_AMBIENT,
    SKY_CLEAR_SRGB,
    SKY_RGB,
    SUN_RGB,
    RoomLight,
    lights_table,
    sun_direction,
)
from anyhome.render.meshes import VERTEX_ATTRS, VERTEX_FORMAT, SceneMeshes

SUPERSAMPLE = 2
"""Default anti-aliasing: the colour pass runs at this many times the image size per
axis and is box-filtered down in linear light. (MSAA would be the usual choice, but
Mesa's software rasterizer shades every sample and costs about twice as much.)"""
SHADOW_MAP_PX = 2048
"""Side of the sun's shadow map."""
SHADOW_PAD_M = 1.0
"""Extra depth range of the shadow map around the house."""
TEXTURE_ANISOTROPY = 1.0
"""Anisotropic filtering of material textures (1: trilinear only; software Mesa pays
about 40 % of a frame for 8; supersampling sharpens grazing floors instead)."""
NEUTRAL_MR = (1.0, 1.0, 1.0, 1.0)
"""The metallicRoughness texel bound for a material without the map: the roughness and
metallic factors pass through unchanged."""
NEUTRAL_NORMAL = (0.5, 0.5, 1.0, 1.0)
"""The normal-map texel bound for a material without the map: the unperturbed normal."""
NORMAL_MAP_KNEE = 0.08
"""Normal-map slopes (tangent of the tilt) well under this are damped: a slope s becomes
s * s / (s + knee). 0.08 (4.6 degrees) keeps 85-95 % of brick and tile edges and about
80 % of a fabric weave but halves plaster's fine stipple (median 4 degrees). 0 applies
the maps as glTF says."""
RELIEF_FADE_COS = 0.4
"""A light whose direction is less than this cosine above a surface (24 degrees) sees its
normal map fade back to the surface normal (to nothing at 0 degrees): a room light hangs
just under the ceiling, which it grazes at a few degrees, and there an unshadowed map
turns the plaster into noise (a real fixture sends its light down). 0 never fades."""
UNIT_BASE, UNIT_MR, UNIT_NORMAL = 2, 3, 4
"""Texture units of a batch's maps (0: the lights table, 1: the sun's shadow map)."""


@dataclass
class Frame:
    """One rendered camera."""

    color: np.ndarray
    """(h, w, 3) uint8 sRGB, row 0 at the top."""
    depth: np.ndarray | None = None
    """(h, w) float32: distance along the optical axis in meters; inf where nothing is drawn."""
    ids: np.ndarray | None = None
    """(h, w) int32: index into ``SceneMeshes.instances``; -1 for sky and ground."""


@dataclass
class _Draw:
    """One uploaded batch: its layer, textures and a vertex array per program."""

    layer: str
    shade: Any
    aux: Any
    depth: Any
    base: Any | None = None
    mr: Any | None = None
    normal: Any | None = None
    normal_scale: float = 1.0
    uniforms: dict[str, Any] = field(default_factory=dict)


def _mat(m: np.ndarray) -> bytes:
    """A row-major numpy matrix as the column-major bytes GLSL expects."""
    return np.asarray(m, dtype=np.float32).T.tobytes()


_SRGB_TO_LINEAR = np.where(
    np.arange(256) / 255.0 <= 0.04045, np.arange(256) / 255.0 / 12.92,
    ((np.arange(256) / 255.0 + 0.055) / 1.055) ** 2.4).astype(np.float32)


def downsample(rgb: np.ndarray, factor: int) -> np.ndarray:
    """Box-filter an sRGB image by ``factor`` per axis, averaging in linear light.

    Parameters
    ----------
    rgb : (h * factor, w * factor, 3) uint8

    Returns
    -------
    (h, w, 3) uint8
    """
    if factor == 1:
        return np.ascontiguousarray(rgb)
    hk, wk, c = rgb.shape
    lin = _SRGB_TO_LINEAR[rgb].reshape(hk // factor, factor, wk // factor, factor, c).mean(axis=(1, 3))
    srgb = np.where(lin <= 0.0031308, lin * 12.92, 1.055 * np.power(lin, 1 / 2.4) - 0.055)
    return np.clip(np.rint(srgb * 255.0), 0, 255).astype(np.uint8)


def _ortho(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """OpenGL orthographic projection of the camera-space box [lo, hi] (z negative ahead)."""
    (x0, y0, zn), (x1, y1, zf) = lo, hi
    near, far = -zf, -zn
    return np.array([
        [2 / (x1 - x0), 0, 0, -(x1 + x0) / (x1 - x0)], [0, 2 / (y1 - y0), 0, -(y1 + y0) / (y1 - y0)],
        [0, 0, -2 / (far - near), -(far + near) / (far - near)], [0, 0, 0, 1],
    ])


class Renderer:
    """Renders one house. Use as a context manager (or call :meth:`release`).

    Parameters
    ----------
    meshes : the house's batches (see :func:`anyhome.render.meshes.scene_meshes`)
    lights : one light per room, in room-index order
    supersample : colour pass resolution factor per axis (1: no anti-aliasing, fastest;
        2 shades four times as many pixels)
    """

    def __init__(self, meshes: SceneMeshes, lights: list[RoomLight],
                 supersample: int = SUPERSAMPLE) -> None:
        if int(supersample) < 1:
            raise RenderError(f"supersample must be 1 or more, got {supersample!r}")
        self._mgl = import_moderngl()
        self.ctx = create_context()
        self.meshes = meshes
        self.supersample = int(supersample)
        ctx = self.ctx
        self._shade = ctx.program(vertex_shader=shaders.SHADE_VERT, fragment_shader=shaders.SHADE_FRAG)
        self._aux = ctx.program(vertex_shader=shaders.AUX_VERT, fragment_shader=shaders.AUX_FRAG)
        self._depth_prog = ctx.program(vertex_shader=shaders.SHADOW_VERT,
                                       fragment_shader=shaders.SHADOW_FRAG)
        self._textures: dict[int, Any] = {}
        self._neutral = {UNIT_MR: self._texel(NEUTRAL_MR), UNIT_NORMAL: self._texel(NEUTRAL_NORMAL)}
        self._draws: list[_Draw] = []
        for batch in meshes.batches:
            vbo = ctx.buffer(batch.vertices.tobytes())
            layout = [(vbo, VERTEX_FORMAT, *VERTEX_ATTRS)]
            vaos = [ctx.vertex_array(p, layout, skip_errors=True)
                    for p in (self._shade, self._aux, self._depth_prog)]
            draw = _Draw(batch.layer, vaos[0], vaos[1], vaos[2], self._texture(batch.texture),
                         self._texture(batch.mr_texture), self._texture(batch.normal_texture),
                         float(batch.normal_scale))
            draw.uniforms = {"u_has_tex": draw.base is not None, "u_has_mr": draw.mr is not None,
                             "u_has_nrm": draw.normal is not None, "u_nrm_scale": draw.normal_scale}
            self._draws.append(draw)
        table = lights_table(lights)
        self._lights = ctx.texture((table.shape[1], 2), 4, table.tobytes(), dtype="f4")
        self._lights.filter = (self._mgl.NEAREST, self._mgl.NEAREST)
        self._n_lights = len(lights)
        self._sun = sun_direction()
        self._shadow_maps: dict[bool, tuple[Any, np.ndarray]] = {}
        self._targets: dict[tuple[int, int], dict[str, Any]] = {}

    # ------------------------------------------------------------ resources
    def _texture(self, image: Any) -> Any:
        if image is None:
            return None
        key = id(image)
        if key not in self._textures:
            rgba = np.asarray(image.convert("RGBA"), dtype=np.uint8)[::-1]  # GL rows go up
            tex = self.ctx.texture((rgba.shape[1], rgba.shape[0]), 4, np.ascontiguousarray(rgba).tobytes())
            tex.build_mipmaps()
            tex.repeat_x = tex.repeat_y = True
            tex.anisotropy = TEXTURE_ANISOTROPY
            self._textures[key] = tex
        return self._textures[key]

    def _texel(self, rgba: tuple[float, float, float, float]) -> Any:
        """A 1 x 1 float texture of one exact value (the neutral stand-in maps)."""
        tex = self.ctx.texture((1, 1), 4, np.asarray(rgba, dtype=np.float32).tobytes(), dtype="f4")
        tex.filter = (self._mgl.NEAREST, self._mgl.NEAREST)
        tex.repeat_x = tex.repeat_y = True
        return tex

    def _target(self, w: int, h: int) -> dict[str, Any]:
        """Framebuffers for a (w, h) image: ``color`` (supersampled) and ``aux`` (instance
        and depth at the image size; without supersampling it shares ``color``'s depth
        buffer and doubles as its depth pre-pass)."""
        if (w, h) not in self._targets:
            ctx = self.ctx
            limit = int(ctx.info.get("GL_MAX_RENDERBUFFER_SIZE", 8192))
            if not (0 < w <= limit and 0 < h <= limit):
                raise RenderError(f"image size {w} x {h} px is outside 1..{limit} px")
            k = max(1, min(self.supersample, limit // max(w, h)))
            depth = ctx.depth_renderbuffer((w * k, h * k))
            color = ctx.framebuffer(ctx.renderbuffer((w * k, h * k), 4), depth)
            aux_depth = ctx.depth_renderbuffer((w, h)) if k > 1 else depth
            aux = ctx.framebuffer(ctx.renderbuffer((w, h), 2, dtype="f4"), aux_depth)
            self._targets[(w, h)] = {"color": color, "aux": aux, "factor": k}
        return self._targets[(w, h)]

    def _shadow_map(self, ceilings: bool) -> tuple[Any, np.ndarray]:
        """The sun's depth map (drawn with or without ceilings) and its plan -> clip matrix."""
        if ceilings not in self._shadow_maps:
            ctx = self.ctx
            lo, hi = self.meshes.bounds
            centre = (lo + hi) / 2
            radius = float(np.linalg.norm(hi - lo)) / 2 + SHADOW_PAD_M
            view = Camera(tuple(centre + self._sun * radius * 2), tuple(centre), 1.0, 1, 1).view_matrix()
            corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                                for z in (lo[2], hi[2])])
            cam = corners @ view[:3, :3].T + view[:3, 3]
            pad = np.array([0.05, 0.05, SHADOW_PAD_M])
            matrix = _ortho(cam.min(axis=0) - pad, cam.max(axis=0) + pad) @ view
            tex = ctx.depth_texture((SHADOW_MAP_PX, SHADOW_MAP_PX))
            tex.compare_func = "<="
            tex.filter = (self._mgl.LINEAR, self._mgl.LINEAR)
            tex.repeat_x = tex.repeat_y = False
            fbo = ctx.framebuffer(depth_attachment=tex)
            fbo.use()
            fbo.clear(depth=1.0)
            self._draw_depth(matrix, ceilings)
            self._shadow_maps[ceilings] = (tex, matrix)
        return self._shadow_maps[ceilings]

    def _draw_depth(self, view_proj: np.ndarray, ceilings: bool) -> None:
        """Depth only (opaque batches) into the bound framebuffer."""
        ctx = self.ctx
        ctx.enable(self._mgl.DEPTH_TEST)
        ctx.disable(self._mgl.CULL_FACE)
        ctx.depth_func = "<"
        self._depth_prog["u_view_proj"].write(_mat(view_proj))
        for draw in self._draws:
            if self._drawn(draw.layer, ceilings, glass=False):
                draw.depth.render()

    def _draw_aux(self, fbo: Any, view: np.ndarray, view_proj: np.ndarray, ceilings: bool) -> np.ndarray:
        """Instance + 1 and depth of the opaque batches into ``fbo``; (h, w, 2) float32, top row first."""
        ctx = self.ctx
        fbo.use()
        fbo.clear(0.0, 0.0, 0.0, 0.0, depth=1.0)
        ctx.enable(self._mgl.DEPTH_TEST)
        ctx.disable(self._mgl.CULL_FACE)
        ctx.depth_func = "<"
        self._set(self._aux, "u_view", _mat(view))
        self._set(self._aux, "u_view_proj", _mat(view_proj))
        for draw in self._draws:
            if self._drawn(draw.layer, ceilings, glass=False):
                draw.aux.render()
        w, h = fbo.size
        data = np.frombuffer(fbo.read(components=2, dtype="f4"), dtype=np.float32)
        return data.reshape(h, w, 2)[::-1]

    @staticmethod
    def _drawn(layer: str, ceilings: bool, glass: bool) -> bool:
        """Whether a batch of ``layer`` is drawn (glass: only in the colour pass)."""
        return (layer != "ceiling" or ceilings) and (layer != "glass" or glass)

    def _set(self, prog: Any, name: str, value: Any) -> None:
        if name in prog:
            if isinstance(value, bytes):
                prog[name].write(value)
            else:
                prog[name].value = value

    # ------------------------------------------------------------ render
    def render(self, camera: Camera, *, ceilings: bool = True, depth: bool = False,
               ids: bool = False) -> Frame:
        """Render ``camera``; ceilings drawn or hidden; depth and instance maps on request.

        A depth pre-pass lays down the nearest surface first, so the costly shading runs
        about once per (supersampled) pixel.
        """
        ctx = self.ctx
        w, h = camera.width_px, camera.height_px
        shadow_tex, shadow_mat = self._shadow_map(ceilings)
        view = camera.view_matrix()
        view_proj = camera.projection_matrix() @ view
        target = self._target(w, h)
        aux = None
        color_fbo = target["color"]
        color_fbo.use()
        color_fbo.clear(*SKY_CLEAR_SRGB, 1.0, depth=1.0)
        k = target["factor"]
        if (depth or ids) and k == 1:  # the aux pass is the pre-pass
            aux = self._draw_aux(target["aux"], view, view_proj, ceilings)
            color_fbo.use()
        else:
            color_fbo.color_mask = (False, False, False, False)
            self._draw_depth(view_proj, ceilings)
            color_fbo.color_mask = (True, True, True, True)
        self._shade_pass(camera, view_proj, shadow_tex, shadow_mat, ceilings)
        rgb = np.frombuffer(color_fbo.read(components=3), dtype=np.uint8).reshape(h * k, w * k, 3)[::-1]
        frame = Frame(color=downsample(rgb, k))
        if (depth or ids) and aux is None:
            aux = self._draw_aux(target["aux"], view, view_proj, ceilings)
        if aux is not None:
            hit = aux[..., 1] > 0
            if depth:
                frame.depth = np.where(hit, aux[..., 1], np.inf).astype(np.float32)
            if ids:
                frame.ids = np.rint(aux[..., 0]).astype(np.int32) - 1
        ctx.depth_func = "<"
        return frame

    def _shade_pass(self, camera: Camera, view_proj: np.ndarray, shadow_tex: Any,
                    shadow_mat: np.ndarray, ceilings: bool) -> None:
        """Lit colour over the laid-down depth (equal depth passes), then glass blended."""
        mgl, ctx, p = self._mgl, self.ctx, self._shade
        for name, value in (
            ("u_view_proj", _mat(view_proj)), ("u_eye", tuple(camera.eye)),
            ("u_sun_dir", tuple(self._sun)), ("u_sun_rgb", SUN_RGB), ("u_sky_rgb", SKY_RGB),
            ("u_ground_rgb", GROUND_BOUNCE_RGB), ("u_indoor_ambient", INDOOR_AMBIENT),
            ("u_n_lights", self._n_lights), ("u_exposure", EXPOSURE), ("u_emissive", EMISSIVE_STRENGTH),
            ("u_shadow_mat", _mat(shadow_mat)), ("u_lights", 0), ("u_shadow", 1),
            ("u_tex", UNIT_BASE), ("u_mr_tex", UNIT_MR), ("u_nrm_tex", UNIT_NORMAL),
            ("u_nrm_knee", float(NORMAL_MAP_KNEE)), ("u_relief_fade", float(RELIEF_FADE_COS)),
        ):
            self._set(p, name, value)
        self._lights.use(0)
        shadow_tex.use(1)
        ctx.enable(mgl.DEPTH_TEST)
        ctx.disable(mgl.CULL_FACE)
        ctx.depth_func = "<="
        ctx.depth_mask = False
        for draw in self._draws:  # glass batches come last
            if not self._drawn(draw.layer, ceilings, glass=True):
                continue
            if draw.layer == "glass":
                ctx.enable(mgl.BLEND)
                ctx.blend_func = mgl.SRC_ALPHA, mgl.ONE_MINUS_SRC_ALPHA
            for name, value in draw.uniforms.items():
                self._set(p, name, value)
            if draw.base is not None:
                draw.base.use(UNIT_BASE)
            (self._neutral[UNIT_MR] if draw.mr is None else draw.mr).use(UNIT_MR)
            (self._neutral[UNIT_NORMAL] if draw.normal is None else draw.normal).use(UNIT_NORMAL)
            draw.shade.render()
        ctx.disable(mgl.BLEND)
        ctx.depth_mask = True

    def release(self) -> None:
        """Free the GL context and everything in it."""
        self.ctx.release()

    def __enter__(self) -> Renderer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.release()
