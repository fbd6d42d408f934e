"""Colour factors in the written GLB are linear, as glTF defines them."""

import pytest

from anyhome.materials.gltf import linear_factors


def test_srgb_factors_become_linear_and_alpha_stays():
    tree = {"materials": [
        {"pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.5, 0.0, 0.3]}, "emissiveFactor": [0.5, 0.5, 0.5]},
        {"pbrMetallicRoughness": {}},
    ]}
    linear_factors(tree)
    r, g, b, a = tree["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"]
    assert (r, b, a) == (1.0, 0.0, 0.3)
    assert g == pytest.approx(0.214, abs=1e-3)  # sRGB 0.5 is linear 0.214
    assert tree["materials"][0]["emissiveFactor"][0] == pytest.approx(0.214, abs=1e-3)
    assert tree["materials"][1] == {"pbrMetallicRoughness": {}}
