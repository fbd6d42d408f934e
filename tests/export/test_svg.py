from __future__ import annotations

import xml.etree.ElementTree as ET

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
