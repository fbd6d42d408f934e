"""Hand-built floorplans and specs, and a validity checker built on anyhome.geometry."""

from __future__ import annotations

import json

import numpy as np
from shapely.geometry import LineString, Polygon

from anyhome.geometry import (
    TOLERANCE_M,
    back_edge,
    blocks_navigation,
    boxes_collide,
    footprint_polygon,
    inside,
    navigability,
    on_boundary,
    opening_zone,
    wall_interval,
)
from anyhome.house import Door, Floorplan, HouseObject, Room, Window
from anyhome.plan.spec import GroupSpec, HouseSpec, ItemSpec, RoomSpec


def rect(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def l_shape(w, h, cw, ch):
    """An L: a w x h rectangle with its top-right cw x ch corner cut off (CCW)."""
    return [(0, 0), (w, 0), (w, h - ch), (w - cw, h - ch), (w - cw, h), (0, h)]


def single_room(polygon, door=((1.0, 0.0), (1.9, 0.0)), windows=(), height=2.7, room_id="r1"):
    room = Room(id=room_id, name="room", type="bedroom", polygon=polygon, height=height)
    doors = [Door(id="d0", rooms=(room_id, "outside"), segment=door)]
    wins = [Window(id=f"w{i}", room=room_id, segment=s) for i, s in enumerate(windows)]
    return Floorplan(rooms=[room], doors=doors, windows=wins, connections=[(room_id, "outside")])


def two_rooms():
    a = Room(id="living", name="living room", type="living_room", polygon=rect(0, 0, 5, 4))
    b = Room(id="bed", name="bedroom", type="bedroom", polygon=rect(5, 0, 8.5, 4))
    doors = [
        Door(id="d0", rooms=("living", "outside"), segment=((1.0, 0.0), (2.0, 0.0))),
        Door(id="d1", rooms=("living", "bed"), segment=((5.0, 1.5), (5.0, 2.4))),
    ]
    wins = [Window(id="w0", room="living", segment=((0.0, 1.0), (0.0, 2.5))),
            Window(id="w1", room="bed", segment=((8.5, 1.0), (8.5, 2.5)))]
    return Floorplan(rooms=[a, b], doors=doors, windows=wins,
                     connections=[("living", "outside"), ("living", "bed")])


def item(name, category, size, rule, **kw):
    return ItemSpec(name=name, category=category, size_m=size, rule=rule, **kw)


def group(name, anchor, members=(), **kw):
    return GroupSpec(name=name, anchor=anchor, members=list(members), **kw)


def house_spec(rooms_groups, connections=None, ornaments=None):
    """rooms_groups: {room_id: [GroupSpec...]}"""
    ornaments = ornaments or {}
    rooms = [RoomSpec(id=rid, name=rid, type="bedroom", area_m2=12.0, groups=gs,
                      ornaments=ornaments.get(rid, [])) for rid, gs in rooms_groups.items()]
    first = rooms[0].id
    return HouseSpec(prompt="test", rooms=rooms, connections=connections or [(first, "outside")])


def rounded(objects):
    """Objects as house.json stores them (floats rounded to 4 decimals)."""
    out = []
    for o in objects:
        d = json.loads(json.dumps(o.model_dump(mode="json")))
        d["position"] = [round(v, 4) for v in d["position"]]
        d["size"] = [round(v, 4) for v in d["size"]]
        d["yaw"] = round(d["yaw"], 4)
        out.append(HouseObject.model_validate(d))
    return out


def check_valid(fp: Floorplan, objects: list[HouseObject], nav_baseline: bool = True, nav: bool = True) -> list[str]:
    """Problems with SCENE_FORMAT rules 1-4 and 6; an empty list means valid."""
    problems = []
    objs = rounded(objects)
    by_id = {o.id: o for o in objs}
    if len(by_id) != len(objs):
        problems.append("duplicate ids")
    rooms = {r.id: Polygon(r.polygon) for r in fp.rooms}
    heights = {r.id: r.height for r in fp.rooms}
    for o in objs:
        poly = footprint_polygon(o.position, o.size, o.yaw)
        if not inside(rooms[o.room], poly):
            problems.append(f"{o.id}: out of its room")
        if o.position[2] + o.size[2] > heights[o.room] + TOLERANCE_M:
            problems.append(f"{o.id}: through the ceiling")
        if o.support == "floor":
            if abs(o.position[2]) > TOLERANCE_M:
                problems.append(f"{o.id}: floor object not on the floor")
            for d in fp.doors:
                zone = opening_zone(d.segment)
                if poly.intersects(zone) and poly.intersection(zone).area > TOLERANCE_M**2:
                    problems.append(f"{o.id}: in front of door {d.id}")
        elif o.support == "wall":
            be = back_edge(o.position, o.size, o.yaw)
            if not on_boundary(rooms[o.room], be):
                problems.append(f"{o.id}: back not on a wall")
            openings = [(d.segment, 0.0, d.height) for d in fp.doors]
            openings += [(w.segment, w.sill, w.sill + w.height) for w in fp.windows]
            for seg, z0, z1 in openings:
                line = LineString(seg)
                if line.distance(LineString(be)) > TOLERANCE_M:
                    continue
                t0, t1, dist = wall_interval(seg, be)
                if dist > TOLERANCE_M:
                    continue
                seg_len = line.length
                overlap_t = min(t1, seg_len) - max(t0, 0.0)
                overlap_z = min(z1, o.position[2] + o.size[2]) - max(z0, o.position[2])
                if overlap_t > TOLERANCE_M and overlap_z > TOLERANCE_M:
                    problems.append(f"{o.id}: covers an opening")
        else:
            sup = by_id.get(o.support)
            if sup is None:
                problems.append(f"{o.id}: unknown supporter {o.support}")
                continue
            if abs(o.position[2] - (sup.position[2] + sup.size[2])) > TOLERANCE_M:
                problems.append(f"{o.id}: not at its supporter's top")
            if not inside(footprint_polygon(sup.position, sup.size, sup.yaw), poly):
                problems.append(f"{o.id}: overhangs its supporter")
    for i, a in enumerate(objs):
        for b in objs[i + 1:]:
            if boxes_collide(a.position, a.size, a.yaw, b.position, b.size, b.yaw):
                problems.append(f"{a.id} collides with {b.id}")
    # rule 6 (only meaningful if the empty floorplan passes)
    rooms_arg = [(r.id, r.polygon) for r in fp.rooms]
    doors_arg = [(d.id, d.rooms, d.segment) for d in fp.doors]
    if nav and (not nav_baseline or navigability(rooms_arg, doors_arg, []).ok):
        obst = [footprint_polygon(o.position, o.size, o.yaw) for o in objs
                if blocks_navigation(o.category, o.size[2], o.support)]
        res = navigability(rooms_arg, doors_arg, obst)
        if not res.ok:
            problems.append(f"not navigable: {res.unreachable_rooms} {res.unreachable_doors}")
    return problems


def front(yaw):
    return np.array([-np.sin(yaw), np.cos(yaw)])
