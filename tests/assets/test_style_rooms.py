"""Issue 12 bug 1 end to end: the planner's style reaches the assets of every room."""

from __future__ import annotations

import anyhome


def _classes_by_family(text: str) -> dict[str, set[str]]:
    house = anyhome.generate(text, seed=0)
    out: dict[str, set[str]] = {}
    for o in house.objects:
        out.setdefault(o.asset["family"], set()).add(o.asset["params"]["style"])
    return out


def test_gothic_victorian_japanese_rooms_get_their_own_asset_class() -> None:
    """Issue 12 bug 1 end to end: the planner's style reaches the assets (before, the
    prose "gothic, pointed arches..." matched no class for gothic and japanese)."""
    got = {s: _classes_by_family(f"a {s} bedroom with a bed, a chair and a table") for s in ("gothic", "victorian", "japanese")}
    common = set.intersection(*(set(g) for g in got.values()))
    assert "bed" in common and len(common) >= 3, common
    for style, by_family in got.items():
        for family in common:
            assert by_family[family] == {style}, (style, family, by_family)
