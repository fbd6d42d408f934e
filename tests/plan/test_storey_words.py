"""Storey words put the rooms they follow or precede on that storey (plan.program._worded_levels)."""

from __future__ import annotations

import numpy as np
import pytest

from anyhome.plan import plan_house
from anyhome.plan.parse import parse


def _levels(text: str, seed: int = 0) -> dict[str, int]:
    spec = plan_house(text, np.random.default_rng(seed))
    return {r.id: r.level for r in spec.rooms}


def test_floor_words_are_found_with_their_place():
    text = "a kitchen on the ground floor, a study on the first floor and a bedroom upstairs"
    words = [w for _, _, w in parse(text).floor_words]
    assert words == ["ground", "first", "upstairs"]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_townhouse_rooms_go_to_the_floors_the_text_names(seed):
    levels = _levels("A three-storey townhouse with a kitchen and dining room on the ground floor, a living room "
                     "and study on the first floor and two bedrooms with a bathroom on the top floor.", seed)
    assert levels["kitchen"] == levels["dining_room"] == 0
    assert levels["living_room"] == levels["study"] == 1
    assert {levels[r] for r in levels if r.startswith(("bedroom", "master_bedroom", "bathroom"))} == {2}


def test_downstairs_and_upstairs_after_a_list():
    levels = _levels("A two-storey family house with the living room, kitchen and a study downstairs "
                     "and three bedrooms and a family bathroom upstairs.")
    assert levels["living_room"] == levels["kitchen"] == levels["study"] == 0  # a study would go up unasked
    assert levels["family_bathroom"] == 1
    assert all(v == 1 for k, v in levels.items() if "bedroom" in k)


def test_american_first_floor_is_the_ground_floor():
    levels = _levels("A two-storey house with a kitchen and a lounge on the first floor and the bedrooms on the second floor.")
    assert levels["kitchen"] == levels["lounge"] == 0
    assert all(v == 1 for k, v in levels.items() if "bedroom" in k)


def test_an_upstairs_after_a_list_takes_only_rooms_that_go_up():
    levels = _levels("a two-storey family house with a long hallway, a kitchen, a living room and three bedrooms upstairs")
    hall = next(k for k in levels if "hallway" in k)
    assert levels[hall] == levels["kitchen"] == levels["living_room"] == 0
    assert all(v == 1 for k, v in levels.items() if "bedroom" in k)


def test_an_upstairs_right_before_a_room_takes_it():
    levels = _levels("A two-storey cottage with a kitchen downstairs, an upstairs sitting room and two bedrooms.")
    assert levels["kitchen"] == 0
    assert levels["upstairs_sitting_room"] == 1


def test_a_room_in_the_attic_goes_up_there_and_the_attic_is_no_room_of_its_own():
    levels = _levels("A two-storey house with a kitchen and a lounge downstairs, two bedrooms upstairs "
                     "and a games room in the attic.")
    assert levels["games_room"] == max(levels.values()) == 2
    assert "attic" not in levels  # "in the attic" places the games room; it names no storage room


def test_rooms_in_the_basement_go_down_and_the_basement_is_no_room_of_its_own():
    levels = _levels("A family house with a home cinema and a wine cellar in the basement and a kitchen, "
                     "a living room and two bedrooms.")
    assert levels["home_cinema"] == levels["wine_cellar"] == -1
    assert "basement" not in levels


@pytest.mark.parametrize("seed", range(3))
def test_a_buildings_main_room_listed_before_basement_words_stays_on_the_entrance_storey(seed):
    """"Two courtrooms, ... and a few holding cells in the basement": the cells go down, the
    courthouse's courtrooms and the rooms listed with them do not."""
    levels = _levels("A courthouse with two courtrooms, a jury room and a few holding cells in the basement.", seed)
    assert levels["courtroom"] == levels["courtroom_2"] == levels["jury_room"] == 0
    assert levels["holding_cell"] == -1


def test_an_attic_named_alone_is_still_a_room():
    levels = _levels("A two-storey cottage with a kitchen, a living room, two bedrooms and an attic.")
    assert levels["attic"] == max(levels.values())


def test_a_room_the_words_put_in_the_attic_replaces_the_planned_attic_storage():
    levels = _levels("A wooden chalet, two floors plus an attic: a kitchen and a lounge on the first floor, "
                     "three bedrooms on the second floor, and a games room in the attic.")
    assert levels["games_room"] == max(levels.values())
    assert "attic" not in levels


def test_a_storey_word_and_an_adverb_are_no_object():
    text = "a small cabin with a sleeping loft upstairs, downstairs just a kitchenette and a shower room"
    assert parse(text).objects == []


def test_an_attic_after_a_list_takes_only_rooms_that_go_up():
    levels = _levels("A farmhouse with a workshop in the basement, a kitchen and a snug, and two bedrooms in the attic.", 3)
    top = max(levels.values())
    assert levels["kitchen"] == levels["snug"] == 0  # a snug is a room (a parlour) of its own
    assert all(v == top for k, v in levels.items() if "bedroom" in k)


def test_an_attic_right_after_a_room_takes_it_whatever_its_type():
    levels = _levels("A two-storey house with a kitchen and a lounge, two bedrooms upstairs and a home cinema in the attic.")
    cinema = next(k for k in levels if "cinema" in k)
    assert levels[cinema] == max(levels.values()) == 2


def test_a_storey_word_opening_a_list_takes_every_room_of_it():
    levels = _levels("a tiny cabin with a sleeping loft upstairs, downstairs just a kitchenette, "
                     "a shower room and a little living area")
    assert levels["sleeping_loft"] == 1
    assert levels["kitchenette"] == levels["shower_room"] == levels["living_area"] == 0


def test_a_trailing_storey_word_does_not_open_the_next_list():
    levels = _levels("a two-storey cottage with two bedrooms upstairs, a kitchen, a living room and a study")
    assert levels["kitchen"] == levels["living_room"] == 0
    assert all(v == 1 for k, v in levels.items() if "bedroom" in k)


def test_an_upstairs_modifier_does_not_open_a_list():
    levels = _levels("a two-storey house with an upstairs study, a kitchen and a living room")
    assert levels["upstairs_study"] == 1
    assert levels["kitchen"] == levels["living_room"] == 0


def test_places_among_the_storeys_name_them():
    text = ("a split-level family home - garage and den on the lower level, kitchen, dining and living room "
            "half a flight up, and 3 bedrooms and 2 baths on the upper level")
    assert parse(text).storeys == 3
    levels = _levels(text)
    assert levels["garage"] == levels["den"] == 0
    assert levels["kitchen"] == levels["living_room"] == levels["dining_room"] == 1
    assert {v for k, v in levels.items() if "bedroom" in k or "bathroom" in k} == {2}


def test_the_storey_holding_the_entry_is_the_ground_floor():
    text = ("Luxury triplex penthouse. Lowest level: home gym, guest bedroom and a shower room. Middle level: "
            "entry foyer, kitchen, dining room and living room. On the top floor, a master bedroom and a study.")
    p = parse(text)
    assert (p.storeys, p.basement) == (2, True)
    levels = _levels(text)
    assert levels["home_gym"] == levels["guest_bedroom"] == levels["shower_room"] == -1
    assert levels["foyer"] == levels["kitchen"] == levels["living_room"] == 0  # one foyer, not an entry and a foyer
    assert "entry" not in levels
    assert levels["master_bedroom"] == levels["study"] == 1


def test_a_duplex_lower_level_is_the_ground_floor_and_up_the_stairs_the_next():
    text = ("Small duplex apartment. Open-plan kitchen and living room plus a guest WC on the lower level, "
            "and a bedroom and bathroom up the stairs.")
    levels = _levels(text)
    assert levels["kitchen"] == levels["living_room"] == levels["guest_wc"] == 0  # not a "plan kitchen"
    assert levels["bedroom"] == levels["bathroom"] == 1


def test_a_finished_basement_named_for_its_rooms_is_no_room_of_its_own():
    levels = _levels("A bungalow with a finished basement. Main floor: living room, kitchen and a bathroom. "
                     "In the basement put a laundry room and a rec room.")
    assert levels["laundry_room"] == levels["rec_room"] == -1
    assert levels["living_room"] == levels["kitchen"] == 0
    assert not any("basement" in k for k in levels)


def test_an_upper_storey_of_many_rooms_opens_off_a_landing():
    spec = plan_house("A two-storey farmhouse with a kitchen and a living room downstairs, and four bedrooms "
                      "and a bathroom upstairs.", np.random.default_rng(0))
    ups = {r.id for r in spec.rooms if r.level == 1}
    landing = next(r for r in spec.rooms if r.level == 1 and r.name == "landing")
    stair = next(r.id for r in spec.rooms if r.level == 1 and "stair" in r.id)
    assert landing.type == "hallway"
    assert [c for c in spec.connections if stair in c] == [(stair, landing.id)]
    assert sum(landing.id in c for c in spec.connections) == len(ups) - 1  # every other room off it


def test_a_numbered_floor_asks_for_that_storey():
    text = ("a Victorian terraced house: parlour and dining room on the ground floor, three bedrooms and a "
            "bathroom on the first floor, and a kitchen in the basement")
    assert parse(text).storeys == 2  # British: the first floor is over the ground floor
    levels = _levels(text)
    assert levels["parlour"] == levels["dining_room"] == 0
    assert all(v == 1 for k, v in levels.items() if "bedroom" in k) and levels["kitchen"] == -1
    assert parse("a house with the bedrooms on the second floor").storeys == 2  # American


def test_a_lower_level_under_the_main_level_is_the_basement_and_no_room_of_its_own():
    levels = _levels("a split-level ranch: family room and garage on the lower level, kitchen and living room "
                     "on the main level, and two bedrooms on the upper level")
    assert levels["family_room"] == levels["garage"] == -1
    assert levels["kitchen"] == levels["living_room"] == 0
    assert not any("basement" in k for k in levels)


def test_street_level_is_the_ground_floor_and_the_first_floor_the_one_above():
    from anyhome.plan.parse import parse

    p = parse("a canal house: kitchen and dining room at street level, a living room on the first floor, bedrooms at the top")
    assert [w for _, _, w in p.floor_words] == ["ground", "first", "top"] and p.storeys >= 2


@pytest.mark.parametrize("seed", [0, 1])
def test_a_room_squeezed_into_the_attic_is_the_attic(seed):
    levels = _levels("Tiny fisherman's cottage: the bedroom is squeezed into the attic, and on the ground floor "
                     "there's a kitchen, a bathroom and a snug little sitting room.", seed)
    bedrooms = [k for k in levels if "bedroom" in k]
    assert len(bedrooms) == 1 and levels[bedrooms[0]] == 1
    assert "attic" not in levels  # the bedroom is the attic: no storage room of that name beside it
    assert levels["kitchen"] == levels["sitting_room"] == 0


def test_downstairs_with_a_room_under_the_eaves_is_two_storeys():
    text = "A small cottage with a kitchen and living room downstairs and a bedroom tucked under the eaves."
    assert parse(text).attic
    levels = _levels(text)
    assert max(levels.values()) == 1  # the eaves are the upstairs, not a storey over one
    assert levels["bedroom"] == 1 and levels["kitchen"] == levels["living_room"] == 0


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_storey_by_storey_list_is_not_a_bed_and_bath_total(seed):
    text = ("Narrow new-build townhouse on four storeys: garage and utility on the ground floor, kitchen and "
            "living room on the first floor, two bedrooms and a bathroom on the second, and a master bedroom "
            "with en suite on the third floor.")
    p = parse(text)
    assert p.bedrooms is None and p.bathrooms is None  # "two bedrooms and a bathroom on the second": one storey's
    spec = plan_house(text, np.random.default_rng(seed))
    by_type: dict[str, list[int]] = {}
    for r in spec.rooms:
        by_type.setdefault(r.type, []).append(r.level)
    assert sorted(by_type["bedroom"]) == [2, 2, 3]
    assert sorted(by_type["bathroom"]) == [2, 3]
    assert "dining_room" not in by_type and "study" not in by_type  # every storey listed: no extras


def test_two_bedrooms_and_a_bathroom_is_still_a_total():
    assert parse("a cottage with two bedrooms and a bathroom").bedrooms == 2


def test_at_the_top_is_the_top_floor():
    levels = _levels("A narrow three-storey canal house with a kitchen and dining room on the ground floor, a living "
                     "room on the first floor and a master bedroom with a bathroom at the top.")
    assert levels["master_bedroom"] == 2 and levels["kitchen"] == 0 and levels["living_room"] == 1
    assert "top" not in [w for _, _, w in parse("a reading nook at the top of the stairs").floor_words]


def test_a_farmhouse_cellar_is_its_basement_and_what_it_is_for_no_rooms():
    text = ("Old two-storey farmhouse with a cellar: farmhouse kitchen, parlour, boot room and pantry on the ground "
            "floor, four bedrooms and a bathroom upstairs, and a cellar for storage and preserves.")
    p = parse(text)
    assert [m.name for m in p.rooms].count("cellar") == 1  # announced before the colon, named again in the list
    assert not any(m.name in ("storage", "preserve") for m in p.rooms)  # "for storage and preserves": its use
    assert p.basement
    levels = _levels(text, 2)
    assert levels["cellar"] == -1 and levels["kitchen"] == levels["parlour"] == 0


def test_a_wine_cellar_is_no_basement():
    assert not parse("a restaurant with a wine cellar").basement


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_basement_named_before_a_room_is_its_storey(seed):
    """"a basement playroom": the playroom is in the basement and no storage room is
    planned there as the basement itself (the playroom went to the top floor)."""
    spec = plan_house("a three-storey house with a basement playroom, a kitchen, a living room and 3 bedrooms",
                      np.random.default_rng(seed))
    down = [r for r in spec.rooms if r.level == -1 and r.type != "stairwell"]
    assert [r.type for r in down] == ["playroom"]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_top_floor_words_closing_a_whole_house_list_leave_the_middle_storeys_their_bedrooms(seed):
    """"... 5 bedrooms, 4 bathrooms, a library and a roof terrace room on the top floor" of a
    four-storey house: the top floor takes the room named last; the bedrooms spread over
    the storeys above the ground floor, five of them, none added to fill a storey."""
    spec = plan_house("large 4 storey house with a basement gym, 5 bedrooms, 4 bathrooms, a library and "
                      "a roof terrace room on the top floor", np.random.default_rng(seed))
    level = {r.id: r.level for r in spec.rooms}
    bedrooms = [r for r in spec.rooms if r.type == "bedroom"]
    assert len(bedrooms) == 5
    assert {r.level for r in bedrooms} >= {1, 2}
    assert level["roof_terrace"] == 3 and level["gym"] == -1


def test_words_closing_a_list_still_take_it_all_when_no_storey_is_left_empty():
    levels = _levels("A three-storey townhouse with a kitchen and dining room on the ground floor, a living room "
                     "and study on the first floor and two bedrooms with a bathroom on the top floor.")
    assert {levels[r] for r in levels if r.startswith(("bedroom", "master_bedroom", "bathroom"))} == {2}


FOUR_BED = ("Four-bedroom detached family home. Ground floor: lounge, kitchen/family room, study, cloakroom. "
            "First floor: master bedroom with en suite and walk-in wardrobe, three further bedrooms, family bathroom.")


def test_a_sentence_opening_with_a_floor_and_a_colon_names_that_storey():
    p = parse(FOUR_BED)
    assert [w for _, _, w in p.floor_words] == ["ground", "first"] and p.storeys == 2


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_four_bedroom_home_listing_its_bedrooms_has_four(seed):
    spec = plan_house(FOUR_BED, np.random.default_rng(seed))
    bedrooms = [r for r in spec.rooms if r.type == "bedroom"]
    assert len(bedrooms) == 4 and {r.level for r in bedrooms} == {1}
    assert {r.level for r in spec.rooms if r.type in ("living_room", "kitchen", "study")} == {0}


@pytest.mark.parametrize(("text", "n"), [
    ("A three-bedroom house with a master bedroom and a kitchen", 3),
    ("A three-bedroom house with a master bedroom, two bedrooms and a kitchen", 3),
    ("A three-bedroom house with a master bedroom, three bedrooms and a kitchen", 4),  # the list says more
    ("a two-bedroom flat with a kitchen", 2),
])
def test_a_bedroom_count_before_the_building_is_the_total_of_those_named_after(text, n):
    spec = plan_house(text, np.random.default_rng(0))
    assert sum(r.type == "bedroom" for r in spec.rooms) == n


def test_an_each_with_list_ends_at_a_comma_and_a_room_of_its_own():
    """"eight bedrooms each with an en suite, and staff quarters": one staff quarters (a
    bedroom), not eight restaurants."""
    p = parse("a mansion with a library, eight bedrooms each with an en suite, and staff quarters on the top floor.")
    counts = {m.name: m.count for m in p.rooms}
    assert counts["en suite"] == 8 and counts["staff quarters"] is None
    spec = plan_house("A three-storey mansion with a ballroom, a library, eight bedrooms each with an en suite, "
                      "and staff quarters on the top floor.", np.random.default_rng(0))
    staff = [r for r in spec.rooms if r.name.startswith("staff quarters")]
    assert [r.type for r in staff] == ["bedroom"]


def test_a_homes_cloakroom_is_its_wc_a_theatres_a_coat_room():
    home = plan_house("Four-bedroom detached family home. Ground floor: lounge, kitchen, cloakroom.",
                      np.random.default_rng(0))
    theatre = plan_house("a theatre with a stage, a foyer, a cloakroom and a bar", np.random.default_rng(0))
    assert next(r.type for r in home.rooms if r.name == "cloakroom") == "bathroom"
    assert next(r.type for r in theatre.rooms if r.name == "cloakroom") == "entry"


def test_further_bedrooms_are_bedrooms():
    spec = plan_house(FOUR_BED, np.random.default_rng(0))
    assert not any("further" in r.name for r in spec.rooms)


def test_a_basement_modifier_places_only_its_own_room():
    """"a three-bedroom cottage with a basement den": the den goes down, not the
    bedrooms named before the word."""
    levels = _levels("a three-bedroom cottage with a basement den, a kitchen, a sitting room and a bathroom", 3)
    assert levels["den"] == -1
    assert all(v == 0 for k, v in levels.items() if "bedroom" in k)


def test_a_downstairs_loo_is_a_wc_on_the_ground_floor():
    spec = plan_house("a two-storey brick semi with a through lounge, a kitchen-diner and a downstairs loo, "
                      "three bedrooms and a bathroom upstairs", np.random.default_rng(5))
    loo = next(r for r in spec.rooms if "loo" in r.name)
    assert loo.type == "bathroom" and loo.level == 0


def test_rooms_underneath_the_lofts_put_the_lofts_upstairs():
    spec = plan_house("A tiny house on wheels with two sleeping lofts at either end, one reached by a ladder and one by "
                      "a storage staircase; underneath them a kitchenette, a compact shower room with a composting "
                      "toilet and a built-in sofa.", np.random.default_rng(0))
    assert {r.level for r in spec.rooms if "loft" in r.name} == {1}
    assert {r.level for r in spec.rooms if r.type == "bathroom"} == {0}


def test_under_the_roof_names_no_room_and_an_aga_is_a_cooker():
    spec = plan_house("A converted Victorian chapel turned into a two-bedroom home with a mezzanine study and a big "
                      "open kitchen under the vaulted roof", np.random.default_rng(11))
    assert not any("roof" in r.name for r in spec.rooms)
    farm = plan_house("A four-bedroom farmhouse with a basement wine cellar, a large kitchen with an Aga, a snug and "
                      "a boot room", np.random.default_rng(11))
    items = [i for r in farm.rooms for g in r.groups for i in [g.anchor, *g.members]]
    assert any(i.name == "aga" and i.category == "stove" for i in items) and not farm.warnings


@pytest.mark.parametrize("seed", [0, 1])
def test_a_room_in_the_roof_of_a_counted_house_is_on_its_top_storey(seed):
    spec = plan_house("A tiny three-storey micro-house on an infill plot: bathroom and kitchenette at street level, "
                      "living room on the first floor, bedroom in the roof.", np.random.default_rng(seed))
    levels = {r.id: r.level for r in spec.rooms}
    assert max(levels.values()) == 2  # three storeys, not a fourth for the roof
    assert [r.level for r in spec.rooms if r.type == "bedroom"] == [2]  # the bedroom asked for, and no other


def test_the_eaves_of_a_two_storey_cottage_are_its_upper_storey_and_of_an_uncounted_one_its_attic():
    counted = _levels("A two-storey cottage with a kitchen and living room downstairs and a bedroom under the eaves.")
    assert max(counted.values()) == 1 and counted["bedroom"] == 1
    assert parse("A cottage with a bedroom under the eaves.").attic
    assert not parse("A two-storey cottage with a bedroom under the eaves.").attic
    assert not parse("A bungalow with a roof terrace, bedroom in the roof terrace.").attic  # a roof terrace is no roof space


def test_a_tiny_houses_loft_above_adds_no_storey():
    spec = plan_house("A tiny house with a kitchen, a bathroom and a sleeping loft above.", np.random.default_rng(0))
    assert {r.level for r in spec.rooms} == {0}  # the loft is in the one storey: no stairwells to pay for
    assert parse("A tiny house with a kitchen, a bathroom and a sleeping loft above.").storeys == 1
