"""raylab.render: the same floats as the C++ renderer, progress, cancellation, the GIL."""

import _thread
import gc
import signal
import subprocess
import sys
import threading
import time
import warnings

import numpy as np
import pytest

import raylab
from conftest import SCENES, read_pfm, run_cli, small_scene


@pytest.mark.parametrize("algorithm", raylab.ALGORITHMS)
def test01_render_bytes_equal_raylab_render_pfm(tmp_path, raylab_exe, algorithm):
    """Python's image holds exactly the floats `raylab render --out F.pfm` writes."""
    pfm = tmp_path / f"{algorithm}.pfm"
    run_cli(raylab_exe, "render", "--algorithm", algorithm, "--size", "32x24", "--spp", 4,
            "--seed", 7, "--out", pfm)
    image = raylab.render(small_scene(), algorithm=algorithm, spp=4, seed=7)
    assert image.shape == (24, 32, 3) and image.dtype == np.float32
    expected = read_pfm(pfm)
    assert image.tobytes() == expected.tobytes()
    assert image.max() > 0


def test02_a_scene_file_renders_as_the_cli_renders_it(tmp_path, raylab_exe):
    pfm = tmp_path / "cornell.pfm"
    run_cli(raylab_exe, "render", "--scene", SCENES / "cornell.json", "--size", "24x24",
            "--spp", 2, "--out", pfm)
    image = raylab.render(small_scene(SCENES / "cornell.json", 24, 24), spp=2)
    assert np.array_equal(image, read_pfm(pfm))


def test03_float64_holds_the_same_values_and_threads_do_not_matter():
    scene = small_scene()
    one = raylab.render(scene, spp=2, threads=1)
    two = raylab.render(scene, spp=2, threads=2, dtype="float64")
    assert two.dtype == np.float64
    assert np.array_equal(one.astype(np.float64), two)


def test04_progress_reports_each_pass_and_the_image_so_far():
    reports = []
    image, stats = raylab.render(small_scene(), spp=8,
                                 progress=lambda f, img: reports.append((f, img.copy())),
                                 with_stats=True)
    fractions = [f for f, _ in reports]
    assert fractions == sorted(fractions) and fractions[-1] == 1.0
    assert np.array_equal(reports[-1][1], image)
    assert stats["spp"] == 8 and not stats["cancelled"]
    assert stats["rays"] == sum(stats["rays_by_kind"].values()) > 0


def test05_progress_returning_false_stops_at_a_complete_pass():
    """A cancelled render returns the image of its last complete pass: the render at
    that spp, as Renderer documents."""
    scene = small_scene()
    image, stats = raylab.render(scene, spp=64, progress=lambda f, img: f < 0.03,
                                 with_stats=True)
    assert stats["cancelled"]
    assert 1 <= stats["spp"] < 64
    assert np.array_equal(image, raylab.render(scene, spp=stats["spp"]))


def test06_ctrl_c_stops_a_long_render_with_keyboard_interrupt():
    """Ctrl-C (here: _thread.interrupt_main, which raises SIGINT's flag as the terminal
    would) stops a render of a million samples per pixel: without cancellation this test
    would run into CTest's timeout."""
    scene = raylab.default_scene()
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        raylab.render(scene, spp=1_000_000, threads=2)
    timer.join()
    # The renderer's threads are gone: the next render runs normally.
    assert raylab.render(small_scene(), spp=1).shape == (24, 32, 3)


def test07_sigint_stops_a_render_in_a_script():
    """A real SIGINT, as a terminal's Ctrl-C sends it, to a script rendering for hours."""
    script = ("import raylab, sys; scene = raylab.default_scene(); print('rendering', flush=True); "
              "raylab.render(scene, spp=1_000_000, threads=2); print('finished')")
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "rendering"
    time.sleep(0.5)  # well into the render
    process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=60)
    assert "finished" not in out
    assert "KeyboardInterrupt" in err and process.returncode != 0


def test08_an_exception_in_the_progress_callback_stops_the_render():
    calls = []

    def progress(fraction, image):
        calls.append(fraction)
        raise ValueError("stop here")

    with pytest.raises(ValueError, match="stop here"):
        raylab.render(raylab.default_scene(), spp=1_000_000, progress=progress)
    assert len(calls) == 1


def test09_the_gil_is_released_while_rendering():
    """Another Python thread runs during a render: were the GIL held for the whole render,
    the loop below would not advance until the render had finished."""
    scene = small_scene(width=160, height=120)
    done = threading.Event()
    worker = threading.Thread(target=lambda: (raylab.render(scene, spp=32), done.set()))
    counts = 0
    worker.start()
    while not done.is_set():
        counts += 1
    worker.join()
    assert counts > 10_000


def test10_the_array_owns_its_pixels():
    """No dangling view: the array keeps the renderer's pixels alive by itself."""
    image = raylab.render(small_scene(), spp=1)
    copy = image.copy()
    view = image[2:5, 3:9]
    del image
    gc.collect()
    for _ in range(3):
        raylab.render(small_scene(), spp=1)  # reuse freed memory if anything was freed
    assert np.array_equal(view, copy[2:5, 3:9])
    assert view.base is not None


def test11_bad_arguments_raise_with_the_value():
    scene = small_scene()
    with pytest.raises(ValueError, match="unknown algorithm 'photon'"):
        raylab.render(scene, algorithm="photon")
    with pytest.raises(ValueError, match=r"spp must be in 1\.\.1048576, not 0"):
        raylab.render(scene, spp=0)
    with pytest.raises(ValueError, match="float32 or float64"):
        raylab.render(scene, spp=1, dtype="int8")


def test12_write_image_writes_what_raylab_render_writes(tmp_path, raylab_exe):
    pfm = tmp_path / "cli.pfm"
    run_cli(raylab_exe, "render", "--size", "32x24", "--spp", 2, "--out", pfm)
    image = raylab.render(small_scene(), spp=2)
    ours = tmp_path / "python.pfm"
    raylab.write_image(image, str(ours))
    assert ours.read_bytes() == pfm.read_bytes()
    assert np.array_equal(raylab.read_pfm(str(ours)), image)
    assert raylab.display_rmse(image, image) == 0.0


def test12c_a_scene_without_light_warns(tmp_path):
    # Nothing gives light: the picture is black, and Python says why, as the command line does.
    dark = tmp_path / "dark.json"
    dark.write_text("""{"raylab_scene": 2, "materials": [{"name": "grey"}],
      "objects": [{"name": "ball", "material": "grey",
                   "shape": {"type": "sphere", "centre": [0, 0, -3], "radius": 1}}],
      "camera": {"width": 16, "height": 16}}""")
    scene = raylab.load_scene(str(dark))
    with pytest.warns(UserWarning, match="the scene has no light"):
        image = raylab.render(scene, spp=1)
    assert image.max() == 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        raylab.render(small_scene(), spp=1)  # a lit scene: no warning


def test12b_write_image_takes_an_8bit_picture_as_it_is(tmp_path):
    # view_image and to_srgb give uint8 sRGB: written as they are, not read as radiance
    # (128 would have been 128 times white).
    image = raylab.render(small_scene(), spp=2)
    linear, picture = tmp_path / "linear.png", tmp_path / "picture.png"
    raylab.write_image(image, str(linear))
    raylab.write_image(raylab.to_srgb(image), str(picture))
    assert picture.read_bytes() == linear.read_bytes()
    grey = np.full((4, 5, 3), 128, np.uint8)
    with pytest.raises(ValueError, match=r"grey\.pfm: an 8-bit sRGB picture .* is written as \.png"):
        raylab.write_image(grey, str(tmp_path / "grey.pfm"))
    assert not (tmp_path / "grey.pfm").exists()
    with pytest.raises(TypeError, match="must hold floats .* or uint8"):
        raylab.write_image(np.full((4, 5, 3), 1, np.int64), str(tmp_path / "ints.png"))
