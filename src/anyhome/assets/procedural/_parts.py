"""Shared pieces of the procedural factories: the parameter record, a mesh builder
made of coloured primitives, each labelled with its material role, and style helpers.

Every part a factory builds says what it is made of (:data:`Role`: wood, fabric, metal,
glass...). A part's role is its ``role=`` argument, else the role its colour carries: a
:class:`Tint` is a colour string with a role (``METAL``, ``GLASS``, ``tint("#f4f1ea",
"ceramic")``), and the three colour slots of a :class:`Params` (``p.primary``...) carry
the roles the family declared with :func:`slot_roles`. ``darker``/``lighter`` keep the
role. A part with neither is an error. :meth:`Builder.mesh` stores the roles per face
(``mesh.face_attributes["role"]``, indices into :data:`ROLES`); the materials read them
(:func:`face_roles`), never guessing from colours.

A factory is a pair ``sample(rng, size, style) -> Params`` and ``build(params) ->
trimesh.Trimesh``. ``build`` uses nothing but its parameters (randomness needed at
build time comes from ``params.seed``), so a mesh can be rebuilt from the record that
``Params.to_record`` writes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from typing import Any, Literal, get_args

import numpy as np
import trimesh

from anyhome.assets.colors import mix, to_rgba
from anyhome.assets.styles import TRAITS, Style, class_name, style_class

Size = tuple[float, float, float]
KNOB_DECIMALS = 4
"""Knobs are rounded like house.json floats so a saved record rebuilds the same mesh."""
CYL_SECTIONS = 16
"""Sections of a cylinder or cone primitive."""

Role = Literal["wood", "fabric", "leather", "metal", "glass", "ceramic", "stone", "plastic", "rubber",
               "paper", "plant", "light", "screen", "paint"]
"""What a part is made of. ``light``: a glowing part (bulb, flame, LED); ``screen``: a
display; ``paint``: a painted or lacquered surface of no other named material."""
ROLES: tuple[Role, ...] = get_args(Role)
ROLE_INDEX: dict[str, int] = {r: i for i, r in enumerate(ROLES)}
ROLE_ATTRIBUTE = "role"
"""Name of the per-face attribute holding role indices."""


class Tint(str):
    """A colour string (``"#rrggbb"``) that carries the material role of what it paints."""

    role: Role

    def __new__(cls, color: str, role: Role) -> Tint:
        if role not in ROLE_INDEX:
            raise ValueError(f"unknown material role {role!r}")
        t = super().__new__(cls, color)
        t.role = role
        return t

    def __reduce__(self):  # keep the role through copy/pickle
        return (Tint, (str(self), self.role))


def tint(color: str | list[str], role: Role) -> Any:
    """``color`` (or each colour of a list) labelled with ``role``."""
    if isinstance(color, list):
        return [Tint(c, role) for c in color]
    return Tint(color, role)


def role_of(color: str, role: Role | None = None) -> Role:
    """The role of a part: ``role`` if given, else the one ``color`` carries."""
    if role is not None:
        if role not in ROLE_INDEX:
            raise ValueError(f"unknown material role {role!r}")
        return role
    r = getattr(color, "role", None)
    if r is None:
        raise ValueError(f"part coloured {color!r} has no material role (pass role= or a Tint)")
    return r


SlotRole = Role | dict[str, Role]
"""A slot's role, or a table ``{colour: role}`` over the slot's candidate colours whose
``""`` entry is the role of every other candidate."""
_SLOT_ROLES: dict[str, tuple[SlotRole, SlotRole, SlotRole]] = {}


def slot_roles(family: str, primary: SlotRole, secondary: SlotRole, accent: SlotRole) -> None:
    """Declare what a family's primary, secondary and accent colours paint: a role per
    slot, or a ``{colour: role}`` table for a slot whose candidates differ in material
    (``{"": "ceramic", BRASS: "metal"}``: a brass lamp base is metal, any other ceramic)."""
    for spec in (primary, secondary, accent):
        table = spec if isinstance(spec, dict) else {"": spec}
        if "" not in table:
            raise ValueError(f"{family}: slot role table needs a '' (default) entry")
        for r in table.values():
            role_of("", r)
    _SLOT_ROLES[family] = (primary, secondary, accent)


def slot_role(family: str, slot: int, color: str) -> Role | None:
    """The role family ``family`` declared for colour ``color`` in slot ``slot`` (0
    primary, 1 secondary, 2 accent); None if the family declared none."""
    roles = _SLOT_ROLES.get(family)
    if roles is None:
        return None
    spec = roles[slot]
    if isinstance(spec, dict):
        return spec.get(str(color).lower(), spec[""])
    return spec


def _size3(values: Any) -> tuple[float, float, float]:
    """A box size (width, depth, height) as three floats."""
    w, d, h = (float(v) for v in values)
    return (w, d, h)


def face_roles(mesh: trimesh.Trimesh) -> list[Role]:
    """The material role of each face of a mesh built by :class:`Builder`."""
    raw = mesh.face_attributes.get(ROLE_ATTRIBUTE) if hasattr(mesh, "face_attributes") else None
    codes = None if raw is None else np.asarray(raw).reshape(-1)
    if codes is None or len(codes) != len(mesh.faces):
        raise ValueError("mesh has no per-face material roles")
    return [ROLES[int(c)] for c in codes]


FABRICS = ["#b9b2a6", "#8c8f94", "#5f6b7a", "#a6896b", "#7d8c74", "#c9c1b4", "#6d5a6e", "#3f4a5a"]
TEXTILE_WHITE = Tint("#eeebe4", "fabric")
METAL = Tint("#9a9da3", "metal")
DARK_METAL = Tint("#3c3d40", "metal")
BLACK = Tint("#1f1f22", "plastic")
"""Black plastic (knobs, handles, housings); paint a black part of another material with
``tint(BLACK, role)``."""
GLASS = Tint("#b8d4de", "glass")


@dataclass(frozen=True)
class Params:
    """Parameters of one procedural asset; enough to rebuild its mesh.

    ``size`` is the box (width x, depth y, height z) in meters; colours are hex strings;
    ``knobs`` are the family's own parameters as sorted ``(name, value)`` pairs and read
    as attributes (``params.leg_style``).
    """

    family: str
    size: Size
    style: str = ""
    primary: str = "#a0714a"
    secondary: str = TEXTILE_WHITE
    accent: str = "#7d8c74"
    seed: int = 0
    knobs: tuple[tuple[str, Any], ...] = field(default=())

    def __post_init__(self) -> None:
        for i, slot in enumerate(("primary", "secondary", "accent")):
            color = str(getattr(self, slot))
            role = slot_role(self.family, i, color)
            # the slot colours carry the roles the family declared (plain strings if none)
            object.__setattr__(self, slot, color if role is None else Tint(color, role))

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__") or name == "knobs":
            raise AttributeError(name)
        for k, v in object.__getattribute__(self, "knobs"):
            if k == name:
                return v
        raise AttributeError(f"{self.family} params have no knob {name!r}")

    def to_record(self) -> dict[str, Any]:
        return {
            "size": [float(s) for s in self.size],
            "style": self.style,
            "primary": str(self.primary),
            "secondary": str(self.secondary),
            "accent": str(self.accent),
            "seed": int(self.seed),
            "knobs": {k: v for k, v in self.knobs},
        }

    @classmethod
    def from_record(cls, family: str, record: dict[str, Any]) -> Params:
        return cls(
            family=family,
            size=_size3(record["size"]),
            style=str(record.get("style", "")),
            primary=str(record.get("primary", "#a0714a")),
            secondary=str(record.get("secondary", TEXTILE_WHITE)),
            accent=str(record.get("accent", "#7d8c74")),
            seed=int(record.get("seed", 0)),
            knobs=_knobs(record.get("knobs", {})),
        )


def _clean(v: Any) -> Any:
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    if isinstance(v, (int, np.integer)):
        return int(v)
    if isinstance(v, (float, np.floating)):
        r = round(float(v), KNOB_DECIMALS)
        return 0.0 if r == 0 else r
    return str(v)


def _knobs(knobs: dict[str, Any]) -> tuple[tuple[str, Any], ...]:
    return tuple(sorted((str(k), _clean(v)) for k, v in knobs.items()))


def make_params(
    family: str,
    rng: np.random.Generator,
    size: Size,
    style: Style,
    primary: list[str] | str,
    secondary: list[str] | str = TEXTILE_WHITE,
    accent: list[str] | str = "#7d8c74",
    **knobs: Any,
) -> Params:
    """Assemble a Params, picking each colour from its candidate list with ``rng``."""

    def pick(c: list[str] | str) -> str:
        return c if isinstance(c, str) else str(c[int(rng.integers(len(c)))])

    return Params(
        family=family,
        size=_size3([max(s, 1e-3) for s in size]),
        style=class_name(style),
        primary=str(pick(primary)),
        secondary=str(pick(secondary)),
        accent=str(pick(accent)),
        seed=int(rng.integers(2**31 - 1)),
        knobs=_knobs(knobs),
    )


# ----------------------------------------------------------------- style helpers
# A style reaches a factory as the StyleClass the assets stage resolved in its knowledge
# base (or, from tools and tests, a style key or class name string, read in the knowledge
# base in force): see anyhome.assets.styles.
def style_is(style: Style, *traits: str) -> bool:
    """Whether the style's asset class has any of ``traits`` (antique, modern,
    industrial, rustic, eastern)."""
    unknown = set(traits) - TRAITS
    if unknown:
        raise ValueError(f"unknown style traits {sorted(unknown)}")
    return bool(style_class(style).traits & set(traits))


def leg_style(rng: np.random.Generator, style: Style) -> str:
    """Leg shape for a style: its class's one shape, else one drawn from its shapes."""
    legs = style_class(style).legs
    return legs[0] if len(legs) == 1 else str(rng.choice(list(legs)))


def wood_tones(style: Style) -> list[str]:
    """Candidate wood colours for a style."""
    return list(style_class(style).woods)


def fabric_tones(style: Style) -> list[str]:
    """Candidate upholstery colours for a style."""
    return list(style_class(style).fabrics)


def _keep_role(c: str, out: str) -> str:
    r = getattr(c, "role", None)
    return Tint(out, r) if r is not None else out


def darker(c: str, t: float = 0.35) -> str:
    """``c`` mixed towards black by ``t``; a :class:`Tint` keeps its role."""
    return _keep_role(c, mix(c, "#000000", t))


def lighter(c: str, t: float = 0.35) -> str:
    """``c`` mixed towards white by ``t``; a :class:`Tint` keeps its role."""
    return _keep_role(c, mix(c, "#ffffff", t))


# ----------------------------------------------------------------- primitives
@lru_cache(maxsize=None)
def _unit_box() -> tuple[np.ndarray, np.ndarray]:
    m = trimesh.creation.box(extents=(1.0, 1.0, 1.0))
    return np.asarray(m.vertices) + 0.5, np.asarray(m.faces)  # [0, 1]^3


@lru_cache(maxsize=None)
def _unit_cylinder(sections: int) -> tuple[np.ndarray, np.ndarray]:
    m = trimesh.creation.cylinder(radius=1.0, height=1.0, sections=sections)
    v = np.asarray(m.vertices).copy()
    v[:, 2] += 0.5  # z in [0, 1]
    return v, np.asarray(m.faces)


@lru_cache(maxsize=None)
def _unit_sphere(subdivisions: int) -> tuple[np.ndarray, np.ndarray]:
    m = trimesh.creation.icosphere(subdivisions=subdivisions, radius=1.0)
    return np.asarray(m.vertices), np.asarray(m.faces)


def rot_x(angle: float) -> np.ndarray:
    return trimesh.transformations.rotation_matrix(angle, [1, 0, 0])


def rot_y(angle: float) -> np.ndarray:
    return trimesh.transformations.rotation_matrix(angle, [0, 1, 0])


def rot_z(angle: float) -> np.ndarray:
    return trimesh.transformations.rotation_matrix(angle, [0, 0, 1])


def move(offset) -> np.ndarray:
    """Translation by ``offset`` (3,) as a 4x4 matrix."""
    t = np.eye(4)
    t[:3, 3] = offset
    return t


def about(matrix: np.ndarray, point) -> np.ndarray:
    """``matrix`` applied about ``point`` instead of the origin."""
    t = np.eye(4)
    t[:3, 3] = point
    ti = np.eye(4)
    ti[:3, 3] = -np.asarray(point, dtype=float)
    return t @ matrix @ ti


class Builder:
    """Accumulates coloured primitives, each with its material role, and emits one
    vertex-coloured mesh fitted to a box whose faces carry their roles.

    Every primitive takes ``role=``; left out, the role is the one its colour carries (a
    :class:`Tint`); a part with no role raises ValueError.
    """

    def __init__(self) -> None:
        self._v: list[np.ndarray] = []
        self._f: list[np.ndarray] = []
        self._c: list[np.ndarray] = []
        self._r: list[np.ndarray] = []
        self._n = 0

    def add(self, vertices: np.ndarray, faces: np.ndarray, color: str, alpha: int = 255,
            transform: np.ndarray | None = None, role: Role | None = None) -> None:
        code = ROLE_INDEX[role_of(color, role)]
        v = np.asarray(vertices, dtype=float)
        if transform is not None:
            v = v @ transform[:3, :3].T + transform[:3, 3]
        f = np.asarray(faces, dtype=np.int64)
        self._v.append(v)
        self._f.append(f + self._n)
        self._c.append(np.tile(to_rgba(color, alpha), (len(v), 1)))
        self._r.append(np.full(len(f), code, dtype=np.uint8))
        self._n += len(v)

    def box(self, lo, hi, color: str, transform: np.ndarray | None = None, alpha: int = 255,
            role: Role | None = None) -> None:
        """Axis-aligned box from corner ``lo`` to corner ``hi``."""
        lo = np.asarray(lo, dtype=float)
        hi = np.asarray(hi, dtype=float)
        v, f = _unit_box()
        self.add(lo + v * (hi - lo), f, color, alpha, transform, role)

    def cbox(self, center, extents, color: str, transform: np.ndarray | None = None,
             alpha: int = 255, role: Role | None = None) -> None:
        """Box by centre and extents."""
        c = np.asarray(center, dtype=float)
        e = np.asarray(extents, dtype=float) / 2
        self.box(c - e, c + e, color, transform, alpha, role)

    def cyl(self, x: float, y: float, z0: float, z1: float, r: float, color: str,
            r_top: float | None = None, sections: int = CYL_SECTIONS, ry: float | None = None,
            transform: np.ndarray | None = None, alpha: int = 255, role: Role | None = None) -> None:
        """Vertical cylinder or cone frustum (``r_top``), elliptic if ``ry`` is given."""
        v, f = _unit_cylinder(sections)
        v = v.copy()
        rt = r if r_top is None else r_top
        scale = r + (rt - r) * v[:, 2]
        yr = (ry if ry is not None else r) / r if r > 0 else 1.0
        v[:, 0] *= scale
        v[:, 1] *= scale * yr
        v[:, 2] = z0 + v[:, 2] * (z1 - z0)
        v[:, 0] += x
        v[:, 1] += y
        self.add(v, f, color, alpha, transform, role)

    def rod(self, a, b, r: float, color: str, sections: int = 12, alpha: int = 255,
            role: Role | None = None) -> None:
        """Cylinder of radius ``r`` from point ``a`` to point ``b``."""
        a = np.asarray(a, dtype=float)
        b = np.asarray(b, dtype=float)
        d = b - a
        length = float(np.linalg.norm(d))
        if length <= 1e-9:
            return
        v, f = _unit_cylinder(sections)
        v = v * np.array([r, r, length])
        m = trimesh.geometry.align_vectors([0, 0, 1], d / length)
        m[:3, 3] = a
        self.add(v, f, color, alpha, m, role)

    def sphere(self, center, radii, color: str, subdivisions: int = 1,
               transform: np.ndarray | None = None, alpha: int = 255, role: Role | None = None) -> None:
        """Ellipsoid; ``radii`` a number or (rx, ry, rz)."""
        v, f = _unit_sphere(subdivisions)
        self.add(v * np.broadcast_to(np.asarray(radii, dtype=float), (3,)) + np.asarray(center),
                 f, color, alpha, transform, role)

    def lathe(self, profile, color: str, x: float = 0.0, y: float = 0.0,
              sections: int = 24, transform: np.ndarray | None = None, role: Role | None = None) -> None:
        """Surface of revolution about a vertical axis; ``profile`` is (n, 2) (radius, z)."""
        prof = np.asarray(profile, dtype=float)
        m = trimesh.creation.revolve(prof, sections=sections)
        v = np.asarray(m.vertices) + np.array([x, y, 0.0])
        self.add(v, m.faces, color, 255, transform, role)

    def add_colored(self, vertices: np.ndarray, faces: np.ndarray, colors: np.ndarray, role: Role) -> None:
        """A part of one ``role`` with its own per-vertex RGBA colours (``colors`` : (n, 4) uint8)."""
        code = ROLE_INDEX[role_of("", role)]
        v = np.asarray(vertices, dtype=float)
        f = np.asarray(faces, dtype=np.int64)
        self._v.append(v)
        self._f.append(f + self._n)
        self._c.append(np.asarray(colors, dtype=np.uint8).reshape(len(v), 4))
        self._r.append(np.full(len(f), code, dtype=np.uint8))
        self._n += len(v)

    def hull(self, points, color: str, alpha: int = 255, transform: np.ndarray | None = None,
             role: Role | None = None) -> None:
        """Convex hull of ``points`` ((n, 3) float): wedges, prisms, tapered slabs."""
        m = trimesh.convex.convex_hull(np.asarray(points, dtype=float))
        self.add(m.vertices, m.faces, color, alpha, transform, role)

    def torus(self, center, major: float, minor: float, color: str, transform: np.ndarray | None = None,
              sections: int = 24, minor_sections: int = 6, role: Role | None = None) -> None:
        """Ring about the vertical axis through ``center`` (then ``transform``, about the origin)."""
        m = trimesh.creation.torus(major, minor, major_sections=sections, minor_sections=minor_sections)
        self.add(np.asarray(m.vertices) + np.asarray(center, dtype=float), m.faces, color, 255, transform,
                 role)

    def extrude_x(self, profile, x0: float, x1: float, color: str, alpha: int = 255,
                  role: Role | None = None) -> None:
        """A polygon in the (y, z) plane (``profile`` : (n, 2) float) extruded from x0 to x1."""
        from shapely.geometry import Polygon

        m = trimesh.creation.extrude_polygon(Polygon(np.asarray(profile, dtype=float)), x1 - x0)
        v = np.asarray(m.vertices)
        # (u, v, t) -> (x = x0 + t, y = u, z = v): a cyclic permutation keeps faces outward
        self.add(np.column_stack([v[:, 2] + x0, v[:, 0], v[:, 1]]), m.faces, color, alpha, role=role)

    def legs(self, xy, z0: float, z1: float, r: float, kind: str, color: str,
             role: Role | None = None) -> None:
        """Legs at the (x, y) points from ``z0`` up to ``z1`` in the given style (``metal``
        legs are metal whatever ``color`` is)."""
        for x, y in xy:
            if kind == "tapered":
                self.cyl(x, y, z0, z1, r * 0.55, color, r_top=r, role=role)
            elif kind == "turned":
                h = z1 - z0
                self.cyl(x, y, z0, z0 + 0.12 * h, r * 0.7, color, r_top=r * 0.9, role=role)
                self.sphere((x, y, z0 + 0.3 * h), (r * 1.3, r * 1.3, 0.16 * h), color, role=role)
                self.cyl(x, y, z0 + 0.1 * h, z0 + 0.75 * h, r * 0.7, color, role=role)
                self.sphere((x, y, z0 + 0.75 * h), (r * 1.15, r * 1.15, 0.08 * h), color, role=role)
                self.box((x - r, y - r, z0 + 0.8 * h), (x + r, y + r, z1), color, role=role)
            elif kind == "metal":
                self.cyl(x, y, z0, z1, r * 0.5, DARK_METAL, sections=10)
            else:
                self.box((x - r, y - r, z0), (x + r, y + r, z1), color, role=role)

    def extend(self, other: Builder, transform: np.ndarray | None = None) -> None:
        for v, f, c, r in zip(other._v, other._f, other._c, other._r, strict=True):
            base = f.min() if len(f) else 0
            vv = v if transform is None else v @ transform[:3, :3].T + transform[:3, 3]
            self._v.append(vv)
            self._f.append(f - base + self._n)
            self._c.append(c)
            self._r.append(r)
            self._n += len(v)

    def mesh(self, size: Size) -> trimesh.Trimesh:
        """One mesh, scaled and moved so its bounds are exactly the box of ``size``:
        x and y centred on 0, bottom at z = 0. ``face_attributes["role"]`` holds each
        face's role (an index into :data:`ROLES`; see :func:`face_roles`)."""
        if not self._v:
            raise ValueError("no parts built")
        v = np.concatenate(self._v)
        f = np.concatenate(self._f)
        c = np.concatenate(self._c)
        r = np.concatenate(self._r)
        target = np.asarray(size, dtype=float)
        lo, hi = v.min(axis=0), v.max(axis=0)
        ext = np.where(hi - lo > 1e-12, hi - lo, 1.0)
        v = (v - lo) / ext * target + np.array([-target[0] / 2, -target[1] / 2, 0.0])
        return trimesh.Trimesh(vertices=v, faces=f, vertex_colors=c, process=False,
                               face_attributes={ROLE_ATTRIBUTE: r})


def corners(w: float, d: float, inset: float) -> list[tuple[float, float]]:
    """Four (x, y) points ``inset`` in from the corners of a w x d rectangle."""
    x, y = w / 2 - inset, d / 2 - inset
    return [(-x, -y), (x, -y), (x, y), (-x, y)]


def lengthwise(size: Size, draw) -> trimesh.Trimesh:
    """Mesh of an object drawn along x: ``draw(builder, length, breadth, height)`` lays the
    long side on x; when the box is deeper than wide the drawing is turned onto y."""
    w, d, h = size
    b = Builder()
    if w >= d:
        draw(b, w, d, h)
        return b.mesh(size)
    draw(b, d, w, h)
    turned = Builder()
    turned.extend(b, rot_z(np.pi / 2))
    return turned.mesh(size)
