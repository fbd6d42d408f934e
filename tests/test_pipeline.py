"""The Python API: generate, save, load."""

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
