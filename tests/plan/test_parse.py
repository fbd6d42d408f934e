"""Text parsing: counts, room and object mentions, styles, materials."""

import pytest

from anyhome.plan.parse import parse, parse_number


@pytest.mark.parametrize(
    ("word", "n"), [("12", 12), ("twelve", 12), ("a", 1), ("an", 1), ("three", 3), ("dozen", 12), ("chair", None)]
)
def test_parse_number(word, n):
    assert parse_number(word) == n


@pytest.mark.parametrize(
    ("text", "beds", "baths"),
    [("A 1B1B apartment", 1, 1), ("a 3b2b house", 3, 2), ("2br 1ba flat", 2, 1), ("a 3 bed 2 bath home", 3, 2)],
)
def test_bed_bath_codes(text, beds, baths):
    p = parse(text)
    assert (p.bedrooms, p.bathrooms) == (beds, baths)


def _rooms(text):
    return {m.key: m.count for m in parse(text).rooms}


def test_room_counts_in_words_and_hyphens():
    assert _rooms("A three-bedroom home with two bathrooms") == {"bedroom": 3, "bathroom": 2}
    assert _rooms("a one-bedroom, one-bathroom house") == {"bedroom": 1, "bathroom": 1}


def test_named_rooms_keep_user_words():
    p = parse("A cottage with a reading nook, a wine cellar, a mudroom and a painting studio")
    assert [m.name for m in p.rooms] == ["reading nook", "wine cellar", "mudroom", "painting studio"]


def test_unknown_room_is_open_vocabulary():
    p = parse("a house with a trophy room")
    assert [m.name for m in p.rooms] == ["trophy room"] and p.rooms[0].key == ""


def test_object_counts_and_plurals():
    p = parse("A conference room with a long table and twelve chairs.")
    objs = {m.key: m for m in p.objects}
    assert objs["chair"].count == 12
    assert objs["table"].name == "long table"
    easels = parse("a painting studio full of easels").objects[0]
    assert easels.key == "easel" and easels.plural and easels.many


def test_objects_attach_to_their_room():
    p = parse("A Victorian house with a parlor, a library full of bookshelves and a master bedroom with a canopy bed.")
    rooms = [m.name for m in p.rooms]
    by_key = {m.key: m for m in p.objects}
    assert rooms[by_key["bookshelf"].room] == "library"
    assert rooms[by_key["bed"].room] == "master bedroom"
    assert by_key["bed"].name == "canopy bed"


def test_adjacent_object_words_merge():
    p = parse("a meditation room with a Buddha statue")
    assert [(m.key, m.name) for m in p.objects] == [("statue", "buddha statue")]


def test_arrangements():
    p = parse("A museum display room with glass cases along the walls and a statue in the center.")
    arr = {m.key: m.arrangement for m in p.objects}
    assert arr == {"display case": "along_walls", "statue": "center"}
    p = parse("A classroom with desks and chairs arranged in neat rows")
    assert {m.arrangement for m in p.objects} == {"rows"}


def test_styles_and_materials():
    p = parse("A mid-century modern two-bedroom house with a blue marble accent in the bathroom.")
    assert p.styles[0] == "midcentury"
    mat = p.materials[0]
    assert mat.phrase == "blue marble accent" and mat.surfaces == ["walls"]
    assert p.rooms[mat.room].key == "bathroom"


def test_building_and_family():
    p = parse("A house for a family of five.")
    assert p.people == 5 and p.building is not None


def test_odd_input_never_raises():
    for text in ["", "   ", "!!!", "日本語のテキスト", "x" * 10000, "a a a a a a", "0 bedrooms"]:
        parse(text)


def test_colour_and_material_words_may_modify_an_unknown_object():
    p = parse("A dressing room with a tufted pink flumph and six steel vorpal tanks.")
    names = [m.name for m in p.objects]
    assert "tufted pink flumph" in names
    assert any(n.endswith("vorpal tank") for n in names)
    assert "pink" in p.colours


def test_a_noun_after_a_room_word_is_an_object_in_that_room():
    p = parse("A riad with a courtyard fountain and two guest bedrooms.")
    court = next(i for i, r in enumerate(p.rooms) if r.name == "courtyard")
    fountain = next(m for m in p.objects if m.name == "fountain")
    assert fountain.room == court


def test_area_and_corner_extend_a_room_name():
    p = parse("A clinic with a kennel area and a café corner.")
    names = [r.name for r in p.rooms]
    assert "kennel area" in names and "café corner" in names
    assert not p.objects


def test_full_of_after_a_room_is_not_an_object():
    p = parse("a painting studio full of easels")
    assert [m.name for m in p.objects] == ["easel"]


def test_rows_of_arranges_what_follows_and_asks_for_many():
    pew = parse("A chapel with two rows of wooden pews facing an altar.").objects[0]
    assert pew.key == "pew" and pew.many and pew.arrangement == "rows" and pew.count is None


def test_possessive_room_names_are_kept_whole():
    p = parse("A bunkhouse with a counselor's room and a washroom.")
    assert "counselor's room" in [r.name for r in p.rooms]


def test_participles_end_an_object_phrase():
    p = parse("A boutique with a raised platform surrounded by mirrors.")
    assert "raised platform" in [m.name for m in p.objects]


def test_unknown_words_before_a_building_are_style_words_only_when_capitalised():
    assert "quaker" in parse("A Quaker meeting house with benches.").style_words
    p = parse("A mid-size accounting office with eight desks.")
    assert p.style_words == [] and p.styles == []


def test_sleeping_n_sets_the_household_size():
    assert parse("A ski chalet sleeping ten, with bunk rooms.").people == 10
    assert parse("a cabin that sleeps 6").people == 6


def test_known_and_unknown_objects_after_a_room_word_go_in_that_room():
    for text, name in (("A villa with a courtyard fountain.", "fountain"), ("A villa with a courtyard flumph.", "flumph")):
        p = parse(text)
        court = next(i for i, r in enumerate(p.rooms) if r.name == "courtyard")
        assert next(m for m in p.objects if m.name == name).room == court


def test_household_members_are_added_up():
    assert parse("A house for two parents and three kids.").people == 5
    assert parse("A house for a couple with twin toddlers: a nursery.").people == 4
    assert not any(m.name == "toddler" for m in parse("A house for a couple with twin toddlers.").objects)


def test_the_building_phrase_keeps_one_plain_modifier():
    assert parse("A sushi restaurant with a counter.").building_phrase == "sushi restaurant"
    assert parse("a two-bedroom apartment").building_phrase == "apartment"


def test_holding_puts_objects_in_the_room():
    """"A recital hall holding a grand piano and 30 audience chairs": the chairs are the
    hall's, not a classroom's."""
    p = parse("A music conservatory with a recital hall holding a grand piano and 30 audience chairs in rows.")
    hall = next(i for i, m in enumerate(p.rooms) if m.key == "recital hall")
    chairs = next(m for m in p.objects if m.name == "audience chair")
    assert (chairs.count, chairs.room) == (30, hall)


@pytest.mark.parametrize("text", ["A fire station with an apparatus bay for two engines.",
                                  "A fire station with an apparatus bay for two fire engines and a kitchen."])
def test_what_a_room_is_for_is_not_a_room(text):
    """"A bay for two engines": the engines are what the bay holds, not two rooms."""
    p = parse(text)
    assert [m.key for m in p.rooms][:1] == ["apparatus bay"] and all("engine" not in m.name for m in p.rooms)
    engines = [m for m in p.objects if "engine" in m.name]
    assert [(m.key, m.count) for m in engines] == [("fire engine", 2)]


def test_each_with_an_en_suite_gives_every_room_one():
    """"six guest rooms, each with an en-suite shower" and "four bedrooms that each have
    their own bathroom": before, one en-suite in all and no bathroom count."""
    p = parse("A hotel with six standard guest rooms, each with an en-suite shower.")
    assert [m.count for m in p.rooms] == [6, 6]
    p = parse("A villa with four bedrooms that each have their own bathroom.")
    assert {m.name: m.count for m in p.rooms} == {"bedroom": 4, "bathroom": 4}
    p = parse("A house with three bedrooms, each with a desk, and a kitchen.")  # the kitchen is one
    assert {m.name: m.count for m in p.rooms} == {"bedroom": 3, "kitchen": 1}


def test_a_pair_of_counts_two():
    p = parse("A workshop with a lathe, a pair of sawhorses and a couple of old stools.")
    counts = {m.name: m.count for m in p.objects}
    assert counts["sawhorse"] == 2 and counts["old stool"] == 2 and counts["lathe"] == 1


def test_a_count_before_a_room_word_and_a_plural_noun_counts_the_noun():
    """"six study carrels": six carrels (before: six study rooms and some carrels)."""
    p = parse("A library with a row of six study carrels and a returns desk.")
    assert [m.count for m in p.rooms if m.name == "study"] == [1]
    assert [m.count for m in p.objects if m.name == "carrel"] == [6]


def test_a_couple_of_things_is_no_couple_of_people():
    """"a couple of armchairs" in a hair salon planned a home for two (a bedroom)."""
    assert parse("A hair salon with four styling stations and a couple of armchairs by the window.").people is None
    assert parse("A flat for a young couple with a balcony.").people == 2


def test_a_single_room_building_is_one_room():
    """"a fire lookout cabin: a single room with a bunk" planned a whole family home."""
    assert parse("A small fire lookout cabin: a single room with a bunk, a wood stove and a map table.").one_room
    assert parse("A one-room fire lookout cabin with a bunk.").one_room
    assert not parse("A cottage with a kitchen and a single room upstairs for guests and two bedrooms.").one_room


def test_a_hedged_count_is_read_as_given():
    """"about twenty pupil desks": twenty (before: an object called "about")."""
    p = parse("A classroom with about twenty pupil desks and roughly 3 whiteboards.")
    assert {m.name: m.count for m in p.objects} == {"pupil desk": 20, "whiteboard": 3}


def test_a_count_per_room_after_the_object_gives_every_room_that_many():
    """"four classrooms with twenty desks each / in each": twenty in every room, where
    "two bathrooms with four sinks" shares the four out."""
    for text in ("A school with four classrooms with twenty desks each.",
                 "A school with four classrooms with twenty desks in each."):
        (desk,) = parse(text).objects
        assert (desk.count, desk.each) == (20, True), text
    (sink,) = parse("A gym with two bathrooms with four sinks.").objects
    assert (sink.count, sink.each) == (2, True)


def test_both_after_two_rooms_gives_each_of_them_what_follows():
    p = parse("Seaside cottage with two bedrooms; both get a pair of single beds and a blanket chest.")
    assert {m.name: (m.count, m.each) for m in p.objects} == {"single bed": (2, True), "blanket chest": (1, True)}


def test_mens_and_womens_rooms_are_two_rooms():
    p = parse("A squash club with three courts and separate men's and women's changing rooms.")
    assert {m.key: m.count for m in p.rooms}.get("changing room") == 2
    assert parse("A gym with changing rooms.").rooms[0].count is None


def test_where_words_are_not_objects():
    """"a juice bar right by the front door", "the roastery visible behind a glass wall"."""
    p = parse("A gym with a little juice bar right by the front door and a roastery visible behind a glass wall.")
    assert not {"right", "visible"} & {m.name for m in p.objects}
    assert {"juice bar", "roastery"} <= {m.key for m in p.rooms}


def test_an_en_suite_shower_is_one_per_en_suite_and_a_suites_own_things_are_its_own():
    p = parse("A hotel: six guest rooms, each with an en-suite shower, and one honeymoon suite "
              "with its own sitting area and a freestanding tub.")
    objs = {m.name: m for m in p.objects}
    assert objs["shower"].each and p.rooms[objs["shower"].room].count == 6
    assert p.rooms[objs["freestanding tub"].room].name == "honeymoon suite"
    # a room named after a list of another room's things is not their room
    p = parse("A kitchen with an island, a dining room and a sofa.")
    assert {m.name: m.room for m in p.objects}["sofa"] is None


def test_a_word_that_is_also_an_adjective_names_a_room_only_as_a_noun():
    """rooms.yaml ``noun_only``: "a cosy snug," and "a buttery" are rooms; "a snug
    bedroom", "feels snug", "solar panels" and "buttery leather" are not."""
    rooms = lambda t: [m.key for m in parse(t).rooms]  # noqa: E731
    assert rooms("A pub with a long bar, a cosy snug, and a beer garden.") == ["snug", "beer garden"]
    assert rooms("A manor with a great hall, the lord's solar above it and a buttery.") == ["great hall", "lord's solar", "buttery"]
    assert rooms("A snug bedroom with a bed.") == ["bedroom"]
    assert rooms("The living room feels snug and warm.") == ["living room"]
    assert rooms("A cabin with solar panels and a buttery leather sofa.") == []
    # the adjective is no room for the open vocabulary either (before: "snug little", a second living room)
    assert [m.name for m in parse("A cottage with a kitchen and a snug little sitting room.").rooms] == ["kitchen", "sitting room"]


def test_what_people_do_in_a_room_is_no_room_and_no_object():
    p = parse("Tiny studio flat: a single main room where I sleep and live, a kitchenette against one wall, "
              "and a compact unit bathroom.")
    assert not any(m.name in ("live", "sleep") for m in [*p.rooms, *p.objects])


def test_a_hyphenated_number_before_a_noun_is_an_adjective_not_a_count():
    """"a three-seater sofa" is one sofa (before: three); "a two-bedroom flat", "a two-car
    garage", "a four-poster bed", "a one-room cabin" and "a 50-square-metre studio" keep
    their numbers."""
    counts = lambda t: [(m.key, m.count) for m in parse(t).objects]  # noqa: E731
    assert counts("A living room with a three-seater sofa and a two-tier shelf.") == [("sofa", 1), ("shelf", 1)]
    assert counts("A cafe with a two-group machine.") == [("espresso machine", 1)]
    assert counts("A bedroom with a four-poster bed.") == [("bed", 1)]
    assert counts("A house with a two-car garage.") == [("car", 2)]
    assert [(m.key, m.count) for m in parse("A two-bedroom flat.").rooms] == [("bedroom", 2)]
    assert parse("A one-room cabin.").one_room and parse("A 50-square-metre studio.").total_m2 == 50.0
