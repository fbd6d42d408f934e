"""The Python API: generate, save, load."""

import pytest

import anyhome
from anyhome.pipeline import STAGES


def test_api_generate_save_load(tmp_path):
    house = anyhome.generate("A bedroom.", seed=1)
    assert set(house.timings_s) == set(STAGES)
    house.save(tmp_path)
    again = anyhome.load(tmp_path)
    assert again.to_json() == house.to_json()


def test_seeds_give_different_floorplans():
    polys = {str([r.polygon for r in anyhome.generate("A 1B1B apartment with a hallway.", seed=s).rooms])
             for s in (0, 1, 2)}
    assert len(polys) == 3


def test_text_must_be_a_string_of_valid_unicode():
    import pytest

    from anyhome.errors import PlanError

    for bad, message in ((123, "must be a string, got int"), (None, "must be a string, got NoneType"),
                         (b"a bedroom", "must be a string, got bytes"),
                         ("a \udcff bedroom", "not valid UTF-8 \\(byte 0xff at character 3\\)"),
                         ("a \ud800 bedroom", "not valid UTF-8 \\(U\\+D800")):
        with pytest.raises(PlanError, match=message):
            anyhome.generate(bad)


def test_write_outputs_all_or_nothing_with_extra(tmp_path):
    """A failure in ``extra`` (the renders) leaves the old folder as it was."""
    import pytest

    from anyhome.errors import RenderError
    from anyhome.pipeline import write_outputs

    old = anyhome.generate("A bedroom.", seed=1)
    files = write_outputs(old, tmp_path / "h", glb=False)
    assert [f.name for f in files] == ["house.json", "floorplan.svg"]
    before = {p.name: p.read_bytes() for p in (tmp_path / "h").iterdir()}

    def failing_render(folder):
        (folder / "birdseye.png").write_bytes(b"half")
        raise RenderError("no EGL")

    with pytest.raises(RenderError):
        write_outputs(anyhome.generate("A kitchen.", seed=1), tmp_path / "h", glb=False, extra=failing_render)
    assert {p.name: p.read_bytes() for p in (tmp_path / "h").iterdir()} == before
    assert [p.name for p in tmp_path.iterdir()] == ["h"]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_staircase_asked_for_in_a_house_of_storeys_is_its_stairs(seed):
    """"... up a steep staircase" of a two-storey cottage: the plan keeps the staircase,
    the house has its flight between the storeys and no staircase furniture beside it,
    nothing dropped for it."""
    from anyhome.pipeline import generate

    h = generate("A tiny two-storey cottage: kitchen and sitting room downstairs, one bedroom and a little "
                 "shower room up a steep staircase.", seed)
    planned = [i for r in h.plan["rooms"] for g in r["groups"] for i in [g["anchor"], *g["members"]]]
    assert any(i["category"] == "staircase" for i in planned)
    assert any(o.category == "stairs" for o in h.objects)
    assert not any(o.category in ("staircase", "spiral_staircase") for o in h.objects)
    assert not any("stair" in d.name for d in h.dropped)
