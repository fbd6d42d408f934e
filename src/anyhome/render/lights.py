"""Lighting: a sun, a sky/ground hemisphere ambient and one ceiling light per room.

Intensities are linear radiance multipliers before exposure and tone mapping. Each
surface takes the light of the room its front faces (see ``meshes``), so a room's
light does not leak through walls into its neighbours.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from anyhome.house import House

SUN_ELEVATION_DEG = 50.0
"""Sun height above the horizon."""
SUN_AZIMUTH_DEG = 215.0
"""Sun bearing, clockwise from north (215: south-west, towards the bird's-eye camera)."""
SUN_RGB = (2.2, 2.08, 1.87)
"""Sun colour and strength."""
SKY_RGB = (0.55, 0.62, 0.72)
"""Ambient light from the sky hemisphere."""
GROUND_BOUNCE_RGB = (0.28, 0.26, 0.23)
"""Ambient light bounced up from the ground."""
INDOOR_AMBIENT = 0.55
"""Share of the sky ambient that reaches indoor surfaces."""
ROOM_LIGHT_RGB = (1.0, 0.86, 0.68)
"""Colour of the ceiling lights."""
ROOM_LIGHT_POWER = 1.6
"""Ceiling light strength at its falloff distance."""
LIGHT_BELOW_CEILING_M = 0.3
"""How far under the ceiling a room's light hangs."""
OPEN_AIR_LIGHT_M = 2.0
"""Height of the light of an open-air room with no wall lantern (it has no ceiling)."""
FIXTURE_GAP_M = 0.05
"""How far under a light fixture's bottom its light sits."""
EMISSIVE_STRENGTH = 2.0
"""Multiplier of glTF emissive colours (light fixtures glow)."""
EXPOSURE = 1.0
"""Exposure before tone mapping."""
SKY_CLEAR_SRGB = (0.74, 0.83, 0.92)
"""Background colour where no geometry is drawn."""


@dataclass(frozen=True)
class RoomLight:
    position: tuple[float, float, float]
    range_m: float
    """Distance at which the light has fallen to half its strength."""
    rgb: tuple[float, float, float]


def sun_direction(elevation_deg: float = SUN_ELEVATION_DEG,
                  azimuth_deg: float = SUN_AZIMUTH_DEG) -> np.ndarray:
    """(3,) unit vector from the house towards the sun (plan frame)."""
    el, az = np.radians(elevation_deg), np.radians(azimuth_deg)
    return np.array([np.cos(el) * np.sin(az), np.cos(el) * np.cos(az), np.sin(el)])


def room_lights(house: House, fixtures: dict[str, np.ndarray] | None = None) -> list[RoomLight]:
    """One light per room, in ``house.rooms`` order: just under the room's light
    fixture when the scene has one (``fixtures``: room id -> (2, 3) bounds; an open-air
    room's wall lantern), else hanging under the ceiling at the room's centre (an
    open-air room: :data:`OPEN_AIR_LIGHT_M` up)."""
    fixtures = fixtures or {}
    out = []
    for room in house.rooms:
        poly = Polygon(room.polygon).buffer(0)
        range_m = max(1.5, 0.6 * float(np.sqrt(poly.area)))
        rgb = (float(ROOM_LIGHT_POWER * ROOM_LIGHT_RGB[0]), float(ROOM_LIGHT_POWER * ROOM_LIGHT_RGB[1]),
               float(ROOM_LIGHT_POWER * ROOM_LIGHT_RGB[2]))
        if room.id in fixtures:
            lo, hi = fixtures[room.id]
            pos = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2] - FIXTURE_GAP_M)
        else:
            c = poly.centroid if poly.contains(poly.centroid) else poly.representative_point()
            top = room.height if not room.open_air else min(room.height, OPEN_AIR_LIGHT_M + LIGHT_BELOW_CEILING_M)
            pos = (c.x, c.y, top - LIGHT_BELOW_CEILING_M)
        out.append(RoomLight((float(pos[0]), float(pos[1]), float(pos[2])), range_m, rgb))
    return out


def lights_table(lights: list[RoomLight]) -> np.ndarray:
    """(2, n, 4) float32 texture rows: position + range, colour + 0."""
    table = np.zeros((2, max(1, len(lights)), 4), dtype=np.float32)
    for i, light in enumerate(lights):
        table[0, i] = (*light.position, light.range_m)
        table[1, i, :3] = light.rgb
    return table
