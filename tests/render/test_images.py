from __future__ import annotations

import numpy as np
import pytest
from render_png import read_png

from anyhome.errors import RenderError
from anyhome.render.images import encode_png, write_npy, write_png
from anyhome.render.renderer import downsample


@pytest.mark.parametrize("shape", [(7, 5, 3), (4, 9, 4), (3, 3)])
def test_png_round_trip(tmp_path, shape) -> None:
    img = np.random.default_rng(0).integers(0, 256, size=shape, dtype=np.uint8)
    path = write_png(tmp_path / "a" / "x.png", img)
    back = read_png(path)
    assert np.array_equal(back.reshape(img.shape), img)


def test_png_rejects_floats() -> None:
    with pytest.raises(RenderError):
        encode_png(np.zeros((2, 2, 3)))


def test_npy_written_atomically(tmp_path) -> None:
    arr = np.arange(6, dtype=np.int32).reshape(2, 3)
    path = write_npy(tmp_path / "ids.npy", arr)
    assert np.array_equal(np.load(path), arr)
    assert not list(tmp_path.glob(".*.tmp"))


def test_downsample_averages_in_linear_light() -> None:
    img = np.zeros((2, 2, 3), dtype=np.uint8)
    img[0, 0] = img[1, 1] = 255
    out = downsample(img, 2)
    assert out.shape == (1, 1, 3)
    assert 185 <= int(out[0, 0, 0]) <= 189  # sRGB of linear 0.5, not 128
    assert np.array_equal(downsample(img, 1), img)
