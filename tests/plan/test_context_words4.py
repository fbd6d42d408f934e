"""Words found missing or misread on dev_context4 (issue 15): each fragment gives the room,
object, building or look it names, and a neighbouring wording does too."""

from __future__ import annotations

import pytest

from anyhome.plan.parse import parse


def _rooms(text: str) -> dict[str, str]:
    return {m.name: m.key for m in parse(text).rooms}


def _objects(text: str) -> dict[str, str]:
    return {m.name: m.key for m in parse(text).objects}


def _program(text: str) -> str | None:
    from anyhome.plan.knowledge import knowledge_base

    p = parse(text)
    return None if p.building is None else knowledge_base().raw("programs")["buildings"][p.building]["program"]


@pytest.mark.parametrize("text", ["the hot press beside the range", "a kitchen with a cast-iron range",
                                  "a back kitchen with a black-leaded range"])
def test_a_range_in_a_kitchen_is_a_stove_not_a_shooting_range(text):
    assert not parse(text).rooms or all(m.key for m in parse(text).rooms)
    assert "stove" in _objects(text).values()


def test_a_range_of_things_is_no_stove():
    objects = _objects("a deli with a wide range of cheeses")
    assert "stove" not in objects.values() and "wide" not in objects


@pytest.mark.parametrize("text, beds", [("2 bed flat, big kitchen", 2), ("a three-bed semi with a garden", 3),
                                        ("4 bed detached house", 4)])
def test_an_estate_agents_bed_count_is_bedrooms_not_beds(text, beds):
    p = parse(text)
    assert p.bedrooms == beds and not any(m.key == "bed" for m in p.objects)


@pytest.mark.parametrize("text, room", [("the privy across the back yard", "privy"), ("an outside loo", "outside loo"),
                                        ("a cross passage to the kitchen", "cross passage"),
                                        ("an open hall with a central hearth", "open hall"),
                                        ("a plunge pool", "plunge pool"), ("a finishing booth", "finishing booth"),
                                        ("a spray booth", "spray booth"), ("a zenana wing", "zenana wing"),
                                        ("four bedrooms off the corredor", "corredor")])
def test_rooms_of_old_houses_and_workplaces_are_known(text, room):
    assert room in _rooms(text)


def test_an_open_hall_is_a_great_hall_and_a_privy_a_toilet():
    from anyhome.plan.knowledge import knowledge_base

    names = knowledge_base().raw("rooms")["names"]
    assert names["open hall"]["type"] == "hall" and names["privy"]["type"] == "bathroom"


def test_rooms_for_rent_are_bedrooms():
    p = parse("a staircase up to four small rooms for rent")
    room = next(m for m in p.rooms)
    assert room.key == "rent room" and room.count == 4


@pytest.mark.parametrize("text, program", [("Narrowboat home, 57 feet long", "home"), ("a canal boat with a galley", "home"),
                                           ("a two-up two-down in Salford", "home"), ("Wealden hall house, c.1450", "home"),
                                           ("treehouse in the old oak for two kids", "treehouse"),
                                           ("a tree house with a rope ladder", "treehouse")])
def test_homes_named_by_their_kind(text, program):
    assert _program(text) == program


def test_a_kind_of_home_before_the_word_home_keeps_its_look():
    from anyhome.plan.knowledge import knowledge_base

    p = parse("Narrowboat home: a saloon and a galley")
    assert "coastal" in knowledge_base().raw("programs")["buildings"][p.building].get("styles", [])
    assert parse("a boutique hotel").building == parse("a hotel").building  # the head still wins elsewhere


def test_a_boats_cabin_is_a_bedroom_and_a_cabin_bed_a_bed():
    assert _rooms("Narrowboat: a saloon, and a cabin with a cross-bed at the stern")["cabin"] == "cabin"
    assert "cabin" not in _rooms("a kids' room with a cabin bed")


@pytest.mark.parametrize("text, style", [("1900s two-up two-down", "victorian"), ("Boomtown saloon, 1880s Colorado", "rustic"),
                                         ("Hong Kong public-housing flat", "chinese"), ("a Beijing courtyard house", "chinese"),
                                         ("Family bakery in Lyon", "french"), ("A Benedictine monk's cell", "monastic"),
                                         ("Wealden hall house", "tudor")])
def test_places_and_periods_name_their_look(text, style):
    assert style in parse(text).styles


@pytest.mark.parametrize("text, key", [("the brass fire pole", "dance pole"), ("round bolsters", "floor cushion"),
                                       ("behind jharokha screens", "room divider"), ("plaster niches", "shelf")])
def test_objects_named_by_other_words(text, key):
    assert key in _objects(text).values()


def test_kept_and_feature_name_no_object():
    names = _objects("the brass fire pole kept as a feature")
    assert "kept" not in names and "feature" not in names


@pytest.mark.parametrize("text, program", [("Joiner's workshop: a machine shop with a table saw", "makerspace"),
                                           ("a carpentry workshop with two benches", "makerspace"),
                                           ("pottery studio - 4 wheels, 2 kilns, glaze room", "pottery_studio"),
                                           ("Portrait photographer's studio in a Brooklyn storefront", "photo_studio"),
                                           ("Quinta in the Douro valley", "home"), ("a restored finca in Mallorca", "home")])
def test_workplaces_and_estates_named_by_their_trade(text, program):
    assert _program(text) == program


def test_a_plain_workshop_or_pottery_in_a_home_text_is_no_building():
    assert _program("3 bedrooms, a kitchen, and a workshop in the garage") != "makerspace"
    assert _program("a living room with pottery on the shelves") is None


@pytest.mark.parametrize("text, room, key", [("the press house has four granite lagares", "press house", "lagar"),
                                             ("a darkroom with enlargers", "darkroom", "enlarger")])
def test_a_trades_room_and_its_things(text, room, key):
    assert room in _rooms(text) and key in _objects(text).values()


def test_an_outbuilding_is_a_room():
    assert "outbuilding" in _rooms("a former bread oven in the outbuilding")


def test_a_room_becoming_another_is_that_room():
    p = parse("the smallest bedroom, right next to ours, is becoming the nursery for the new baby")
    assert [m.name for m in p.rooms] == ["nursery"]


@pytest.mark.parametrize("text, n", [("a snug on the mezzanine, and three en-suite bedrooms", 3), ("two ensuite bedrooms and a kitchen", 2)])
def test_en_suite_bedrooms_are_that_many_bedrooms_each_with_its_bathroom(text, n):
    rooms = parse(text).rooms
    bedrooms = next(m for m in rooms if m.key == "bedroom")
    ensuites = next(m for m in rooms if m.key in ("en-suite", "ensuite"))
    assert bedrooms.count == n and ensuites.count == n


def test_cauldrons_over_fire_holes_are_cauldrons_and_the_holes_nothing():
    objects = _objects("a bueok kitchen with iron cauldrons set over the fire holes")
    assert "cauldron" in objects.values() and not any("hole" in n for n in objects)


def test_an_oxford_college_set_has_a_scholars_look():
    assert "dark_academia" in parse("Oxford college staircase, a fellow's set: a book-lined study").styles


@pytest.mark.parametrize("text, key", [("a granny annexe over the garage", "granny annexe"), ("a summerhouse at the end of the garden", "summerhouse"),
                                       ("a coach house", "coach house"), ("a garden office", "garden office"),
                                       ("a cleaner's cupboard", "cleaner's cupboard"), ("a tea point", "tea point"),
                                       ("a shed at the bottom of the garden", "shed")])
def test_a_homes_outbuildings_and_small_rooms_are_rooms(text, key):
    assert key in _rooms(text).values()


def test_a_shed_roof_is_no_shed():
    assert "shed" not in _rooms("a cabin with a shed roof")


@pytest.mark.parametrize("text, key", [("a room with a brass bed and a press for the linen", "wardrobe"),
                                       ("the press room with a rotary press", "printing press"),
                                       ("a kitchen with a French press", "espresso machine"),
                                       ("an old cider press in the barn", "wine press")])
def test_a_press_is_a_cupboard_unless_it_says_what_it_presses(text, key):
    assert key in _objects(text).values()
    assert "wardrobe" not in _objects("the press room with a rotary press").values()


def test_out_names_no_object():
    assert "out" not in _objects("a covered walkway out to the boarding ramp")
