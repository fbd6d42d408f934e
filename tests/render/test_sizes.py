"""render_house checks its sizes before any work: no folder created, no renderer started."""

import numpy as np
import pytest

from anyhome.errors import RenderError
from anyhome.render.api import MAX_IMAGE_PX, MAX_TARGET_PX, check_image_sizes, render_house


@pytest.mark.parametrize("kwargs, message", [
    ({"size_px": 8192}, "size_px must be an integer from 1 to 4096"),
    ({"size_px": 0}, "size_px must be"),
    ({"view_size_px": -1}, "view_size_px must be"),
    ({"view_size_px": 2.5}, "view_size_px must be"),
    ({"size_px": True}, "size_px must be"),
    ({"supersample": 0}, "supersample must be"),
    ({"supersample": 4, "size_px": 4096}, f"more than {MAX_TARGET_PX} px"),
])  # fmt: skip
def test_bad_sizes_fail_before_any_work(house, tmp_path, kwargs, message):
    out = tmp_path / "never"
    with pytest.raises(RenderError, match=message):
        render_house(house, out, **kwargs)
    assert not out.exists()


def test_sizes_in_range_pass():
    check_image_sizes(1, MAX_IMAGE_PX)
    check_image_sizes(np.int64(64), 32, supersample=1, names=("--size", "--view-size"))
    with pytest.raises(RenderError, match="--view-size must be"):
        check_image_sizes(64, 0, names=("--size", "--view-size"))
