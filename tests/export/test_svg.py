from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from anyhome.export import write_svg

NS = "{http://www.w3.org/2000/svg}"


def test_svg_parses_and_has_rooms(small_house, tmp_path) -> None:
    path = write_svg(small_house, tmp_path / "plan.svg")
    root = ET.parse(path).getroot()
    assert root.tag == f"{NS}svg"
    texts = [t.text for t in root.iter(f"{NS}text")]
    for room in small_house.rooms:
        assert room.name in texts
    rooms = [p for p in root.iter(f"{NS}polygon") if p.get("class") == "room"]
    assert {p.get("id") for p in rooms} == {f"room-{r.id}" for r in small_house.rooms}
    assert any(t and t.endswith("m²") for t in texts)
    assert any(p.get("class") == "window" for p in root.iter(f"{NS}polygon"))
    assert any(el.get("class") == "door" for el in root.iter(f"{NS}line"))
    assert root.find(f".//{NS}g[@id='scale']") is not None
    assert not list(tmp_path.glob(".*.tmp"))


def test_north_is_up(small_house, tmp_path) -> None:
    root = ET.parse(write_svg(small_house, tmp_path / "p.svg")).getroot()
    sofa = next(p for p in root.iter(f"{NS}polygon") if p.get("id") == "object-sofa1")
    bed = next(p for p in root.iter(f"{NS}polygon") if p.get("id") == "object-ns")
    y = lambda el: sum(float(q.split(",")[1]) for q in el.get("points").split()) / 4  # noqa: E731
    assert y(sofa) < y(bed)  # the sofa (plan y 3.5) is drawn above the nightstand (plan y 0.25)


# ---------------------------------------------------------------- hostile text
HOSTILE = [
    '" onmouseover="alert(document.cookie)',
    "x' onload='alert(1)",
    "<script>alert(1)</script>",
    "a & b ]]> <!-- c",
    "\x1b]0;pwned\x07title \x1b[31mred\x1b[0m",
    "ctl \x00\x01\x08\x0b\x0c\x1f\x7f\x85 end",
    "bidi \u202e\u2066gnp.exe\u2069",
    "\ud800 lone surrogate \ufffe\uffff",
    "new\nline\rcr\ttab",
]
"""Strings a house.json (or an LLM) may carry in names, categories and the prompt."""

SVG_ATTRIBUTES = {
    "xmlns", "width", "height", "viewBox", "font-family", "font-size", "font-weight", "x", "y",
    "fill", "fill-opacity", "stroke", "stroke-width", "stroke-linecap", "stroke-dasharray",
    "text-anchor", "dominant-baseline", "id", "class", "points", "x1", "y1", "x2", "y2", "d",
}
"""Every attribute the exporter writes."""

_XML_ILLEGAL = set(range(0x00, 0x20)) - {0x09, 0x0A, 0x0D} | {0xFFFE, 0xFFFF} | set(range(0xD800, 0xE000))


def _hostile_house(small_house, ids: bool):
    """``small_house`` with hostile text everywhere; with ``ids`` also hostile ids (built
    around validation with model_copy, as a defence-in-depth check of the exporter)."""
    h = small_house.model_copy(update={"prompt": " | ".join(HOSTILE)})
    rooms, objects = [], []
    for i, r in enumerate(h.rooms):
        update = {"name": HOSTILE[i % len(HOSTILE)], "style": HOSTILE[-1]}
        if ids:
            update["id"] = f'{r.id}" onmouseover="alert({i})'
        rooms.append(r.model_copy(update=update))
    ren = {r.id: n.id for r, n in zip(h.rooms, rooms, strict=True)}
    for i, o in enumerate(h.objects):
        update = {"name": HOSTILE[(i + 3) % len(HOSTILE)], "category": HOSTILE[i % len(HOSTILE)],
                  "room": ren[o.room]}
        if ids:
            update["id"] = f"{o.id}' onclick='x{i}"
        objects.append(o.model_copy(update=update))
    doors = [d.model_copy(update={"rooms": tuple(ren.get(r, r) for r in d.rooms),
                                  **({"id": f'{d.id}"><script>x</script>'} if ids else {})})
             for d in h.doors]
    windows = [w.model_copy(update={"room": ren[w.room], **({"id": f'{w.id}" style="x'} if ids else {})})
               for w in h.windows]
    return h.model_copy(update={"rooms": rooms, "objects": objects, "doors": doors, "windows": windows})


@pytest.mark.parametrize("ids", [False, True], ids=["hostile-text", "hostile-ids"])
def test_hostile_text_cannot_inject(small_house, tmp_path, ids) -> None:
    house = _hostile_house(small_house, ids)
    path = write_svg(house, tmp_path / "plan.svg")
    raw = path.read_text(encoding="utf-8")
    assert not _XML_ILLEGAL & {ord(c) for c in raw}
    assert "\x1b" not in raw and "\u202e" not in raw
    root = ET.parse(path).getroot()  # well-formed XML
    tags = {el.tag.removeprefix(NS) for el in root.iter()}
    assert tags <= {"svg", "title", "rect", "g", "polygon", "line", "text", "path"}
    for el in root.iter():
        assert set(el.attrib) <= SVG_ATTRIBUTES, el.attrib
    found = {el.get("id") for el in root.iter() if el.get("class") in ("room", "object", "window", "door")}
    expected = ({f"room-{r.id}" for r in house.rooms} | {f"object-{o.id}" for o in house.objects}
                | {f"window-{w.id}" for w in house.windows} | {f"door-{d.id}" for d in house.doors})
    assert found == expected  # every id arrives whole, as the value of the id attribute
    titles = [t.text or "" for t in root.iter(f"{NS}title")]
    assert any("<script>alert(1)</script>" in t for t in titles)  # markup arrives as text, not elements
    assert any("title red" in t for t in titles)  # escape sequences gone, text kept


def test_hostile_house_json_round_trip_exports_clean_svg(small_house, tmp_path) -> None:
    """Through a real file: hostile names load (names are free text) and export clean."""
    from anyhome.house import load

    house = _hostile_house(small_house, ids=False)
    house.save(tmp_path)
    path = write_svg(load(tmp_path), tmp_path / "floorplan.svg")
    root = ET.parse(path).getroot()
    for el in root.iter():
        assert set(el.attrib) <= SVG_ATTRIBUTES

