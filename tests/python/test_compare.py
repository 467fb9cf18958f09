"""raylab.compare: the four algorithms against a reference, as a dict and arrays."""

import json

import numpy as np
import pytest

import raylab
from conftest import small_scene


@pytest.fixture(scope="module")
def comparison():
    return raylab.compare(small_scene(), spp=4, reference_spp=16, seed=3)


def test01_each_image_is_the_render_of_that_algorithm(comparison):
    scene = small_scene()
    assert [a["algorithm"] for a in comparison["algorithms"]] == list(raylab.ALGORITHMS)
    for figures in comparison["algorithms"]:
        image = raylab.render(scene, algorithm=figures["algorithm"], spp=4, seed=3)
        assert np.array_equal(figures["image"], image)
        assert figures["stats"]["spp"] == 4


def test02_the_reference_is_path_tracing_at_its_own_seed(comparison):
    reference = comparison["reference"]
    assert reference["spp"] == 16 and reference["seed"] != 3
    image = raylab.render(small_scene(), algorithm="path", spp=16, seed=reference["seed"])
    assert np.array_equal(reference["image"], image)


def test03_errors_and_series_are_measured_against_the_reference(comparison):
    reference = comparison["reference"]["image"]
    report = json.loads(comparison["json"])
    for figures in comparison["algorithms"]:
        assert figures["rmse"] == raylab.display_rmse(figures["image"], reference)
        assert figures["rmse_linear"] == raylab.rmse(figures["image"], reference)
        series = figures["series"]
        assert list(series["spp"]) == [1, 2, 4]
        assert series["rmse"][-1] == figures["rmse"]
        assert np.all(np.diff(series["rays"]) > 0)
    assert comparison["mode"] == "equal samples"
    assert report["scene"] == comparison["scene"]


def test04_a_reference_array_is_used_as_given():
    scene = small_scene()
    reference = raylab.render(scene, algorithm="path", spp=8, seed=11)
    result = raylab.compare(scene, spp=1, algorithms=["whitted"], reference=reference)
    assert np.array_equal(result["reference"]["image"], reference)
    with pytest.raises(raylab.ComparisonError):
        raylab.compare(scene, spp=1, algorithms=["whitted"], reference=reference[:10])


def test05_progress_names_each_stage_and_an_exception_stops_it():
    stages = []
    raylab.compare(small_scene(width=8, height=6), spp=2, reference_spp=4,
                   progress=lambda stage, fraction, spp: stages.append(stage))
    assert stages[0] == "reference" and "path" in stages

    def stop(stage, fraction, spp):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        raylab.compare(raylab.default_scene(), spp=100_000, progress=stop)
