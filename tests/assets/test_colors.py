from anyhome.assets.colors import material_color


def test_material_words() -> None:
    walnut = material_color("dark walnut")
    oak = material_color("white oak")
    assert walnut is not None and oak is not None
    assert int(walnut[1:3], 16) < int(oak[1:3], 16)  # dark walnut is darker than white oak
    assert material_color("pink") == material_color("pink velvet")
    assert material_color("no colour here") is None


def test_muting_words_grey_a_colour_without_darkening_it_much() -> None:
    def rgb(text: str) -> list[int]:
        c = material_color(text)
        assert c is not None
        return [int(c[i : i + 2], 16) for i in (1, 3, 5)]

    plain, faded = rgb("burgundy"), rgb("faded burgundy")
    assert max(faded) - min(faded) < 0.6 * (max(plain) - min(plain))  # less saturated
    assert abs(sum(faded) - sum(plain)) < 0.25 * sum(plain)  # about as light
    assert rgb("peeling faded burgundy damask wallpaper") == faded
