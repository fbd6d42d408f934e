from anyhome.assets.colors import material_color


def test_material_words() -> None:
    walnut = material_color("dark walnut")
    oak = material_color("white oak")
    assert walnut is not None and oak is not None
    assert int(walnut[1:3], 16) < int(oak[1:3], 16)  # dark walnut is darker than white oak
    assert material_color("pink") == material_color("pink velvet")
    assert material_color("no colour here") is None
