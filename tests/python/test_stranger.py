"""Issue 38 from Python: NaN and infinite rays, thread counts and sample counts are refused
with a ValueError before any work (they killed the interpreter: SIGFPE from GMP, or
std::terminate when thread creation failed), and a NaN reference is refused."""

import math

import numpy as np
import pytest

import raylab
from conftest import small_scene


@pytest.mark.parametrize(
    "origin, direction",
    [((math.nan, 0, 0), (0, 0, 1)), ((0, 0, 0), (0, 0, math.inf)), ((0, 0, 0), (math.nan, 0, 1))],
)
def test01_a_ray_refuses_nan_and_infinities(origin, direction):
    with pytest.raises(ValueError):
        raylab.Ray(origin, direction)


def test02_a_rays_fields_refuse_them_too_and_the_oracle_stays_exact():
    ray = raylab.Ray((0, 0, 5), (0, 0, -1))
    with pytest.raises(ValueError):
        ray.origin = (math.nan, 0, 0)
    with pytest.raises(ValueError):
        ray.direction = (0, math.inf, 0)
    with pytest.raises(ValueError):
        ray.t_min = math.nan
    ray.t_max = math.inf  # no bound: allowed
    sphere = raylab.Sphere((0, 0, 0), 1.0)
    assert raylab.exact_classify(sphere, ray).t == pytest.approx(4.0)
    assert raylab.oracle_compare(sphere, ray).agree
    # A huge direction is normalised without overflowing to a zero vector.
    assert raylab.Ray((0, 0, 5), (0, 0, -1e300)).direction == (0.0, 0.0, -1.0)


def test03_thread_and_sample_counts_are_bounded_before_the_work():
    scene = small_scene()
    with pytest.raises(ValueError, match="threads must be in 0..256"):
        raylab.render(scene, spp=1, threads=30000)
    with pytest.raises(ValueError, match="threads must be in 0..256"):
        raylab.compare(scene, spp=1, threads=20000)
    with pytest.raises(ValueError, match="threads must be in 0..256"):
        raylab.compare(scene, spp=1, threads=-3)
    with pytest.raises(ValueError, match="spp must be in 1..1048576"):
        raylab.compare(scene, spp=2**31 - 1)
    with pytest.raises(ValueError, match="max_depth must be in 0..64"):
        raylab.render(scene, spp=1, max_depth=1000)


def test04_a_nan_reference_is_refused():
    scene = small_scene()
    image = raylab.render(scene, spp=1)
    image[0, 0, 0] = np.nan
    with pytest.raises(ValueError, match="finite"):
        raylab.compare(scene, spp=1, reference=image)
