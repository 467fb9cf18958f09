"""Scenes from Python: files, values read and changed with the loader's rules and messages."""

import json

import pytest

import raylab
from conftest import SCENES, SOURCE_DIR


def test01_default_scene_has_the_original_programs_objects():
    scene = raylab.default_scene()
    assert scene.origin == "untitled.json"
    assert scene.size == (320, 240)
    assert "red sphere" in scene.object_names
    assert "blue cube" in scene.object_names
    assert len(scene.objects) == len(scene.object_names)
    assert scene.camera["width"] == 320


def test02_load_reads_a_shipped_scene_and_to_json_round_trips(tmp_path):
    scene = raylab.load_scene(str(SCENES / "materials.json"))
    assert scene.origin.endswith("materials.json")
    saved = tmp_path / "copy.json"
    scene.save(str(saved))
    again = raylab.load_scene(str(saved))
    assert again.to_json() == scene.to_json()
    assert json.loads(saved.read_text()) == scene.get()


def test03_a_missing_file_raises_naming_it():
    with pytest.raises(raylab.SceneError, match="no-such-scene.json"):
        raylab.load_scene("no-such-scene.json")


def test04_a_syntax_error_names_the_file_and_line(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"raylab_scene": 2,\n "materials": [\n')
    with pytest.raises(raylab.SceneError) as error:
        raylab.load_scene(str(bad))
    assert str(error.value).startswith(f"{bad}:3:1: JSON syntax error")


BAD_VALUES = [
    ("/materials/0/ior", -1.0),
    ("/objects/0/shape/radius", 0),
    ("/camera/vertical_fov", "wide"),
    ("/render/spp", 0),
    ("/render/algorithm", "photon mapping"),
    ("/objects/1/material", "no such material"),
    ("/camera/colour", [1, 2, 3]),
]


@pytest.mark.parametrize("pointer,value", BAD_VALUES)
def test05_a_bad_value_raises_the_loaders_own_message(tmp_path, pointer, value):
    """The message of scene.set equals the one loading a file with that value gives."""
    scene = raylab.default_scene()
    if pointer.startswith("/objects/0/shape/radius"):
        index = scene.object_names.index("red sphere")
        pointer = f"/objects/{index}/shape/radius"
    before = scene.to_json()
    with pytest.raises(raylab.SceneError) as from_python:
        scene.set(pointer, value)
    assert scene.to_json() == before  # the scene stays as it was

    # The same value written into a file and loaded.
    document = json.loads(before)
    parent, key = pointer.rsplit("/", 1)
    node = document
    for part in parent.strip("/").split("/"):
        node = node[int(part)] if isinstance(node, list) else node[part]
    node[int(key) if isinstance(node, list) else key] = value
    path = tmp_path / "edited.json"
    path.write_text(json.dumps(document))
    with pytest.raises(raylab.SceneError) as from_file:
        raylab.load_scene(str(path))
    expected = str(from_file.value).replace(str(path), "untitled.json", 1)
    assert str(from_python.value) == expected
    assert pointer.split("/")[1] in str(from_python.value)


def test06_set_and_get_change_values_through_the_loader():
    scene = raylab.default_scene()
    scene.set("/render/spp", 3)
    scene.set_camera(vertical_fov=30, width=64, height=48)
    scene.set_material(scene.material_names[0], colour=[0.25, 0.5, 0.75])
    assert scene.get("/render/spp") == 3
    assert scene.size == (64, 48)
    assert scene.camera["vertical_fov"] == 30
    assert scene.materials[0]["colour"] == [0.25, 0.5, 0.75]


def test07_update_applies_all_values_or_none():
    scene = raylab.default_scene()
    before = scene.to_json()
    with pytest.raises(raylab.SceneError, match="/render/spp"):
        scene.update({"/camera/width": 100, "/render/spp": -5})
    assert scene.to_json() == before
    scene.update({"/camera/width": 100, "/render/spp": 5})
    assert scene.size[0] == 100 and scene.render_settings["spp"] == 5


def test08_a_place_the_file_does_not_have_is_refused():
    scene = raylab.default_scene()
    with pytest.raises(raylab.SceneError, match="no such place"):
        scene.set("/objects/99/name", "x")


def test09_object_edits_are_the_windows_edits():
    scene = raylab.default_scene()
    count = len(scene.object_names)
    cube = f"/objects/{scene.object_names.index('blue cube')}"
    before = scene.get(cube)
    scene.rotate_object("blue cube", 30, axis=(0, 1, 0))
    after = scene.get(cube)
    # The file keeps the shape as written and gains the turn as readable steps, about the
    # cube's centre.
    assert after["shape"] == before["shape"]
    centre = before["shape"]["centre"]
    assert after["transform"][-3:] == [
        {"translate": pytest.approx([-c for c in centre])},
        {"rotate": {"axis": [0.0, 1.0, 0.0], "degrees": 30.0}},
        {"translate": pytest.approx(centre)},
    ]
    scene.duplicate_object("red sphere")
    assert len(scene.object_names) == count + 1
    copy_name = scene.object_names[-1]
    assert copy_name == "red sphere copy"
    scene.rename_object(copy_name, "twin")
    with pytest.raises(raylab.SceneError, match="twin"):
        scene.rename_object("red sphere", "twin")  # names stay unique: the loader's rule
    scene.remove_object("twin")
    assert len(scene.object_names) == count
    assert scene.add_shape("sphere") in scene.object_names
    assert scene.add_shape("triangle") == "triangle"
    # The shapes that can be added come from core's table of shape descriptors.
    with pytest.raises(ValueError,
                       match="unknown shape 'mesh': use sphere, box, plane, quad or triangle$"):
        scene.add_shape("mesh")
    with pytest.raises(KeyError, match="no object named 'nothing'"):
        scene.remove_object("nothing")
    with pytest.raises(raylab.SceneError):
        scene.scale_object("blue cube", 0)


def test10_copies_and_renders_keep_their_own_scene():
    scene = raylab.default_scene()
    copy = scene.copy()
    scene.set_camera(width=8, height=6)
    assert copy.size == (320, 240)
    assert raylab.render(scene, spp=1).shape == (6, 8, 3)


def test11_saving_into_a_missing_folder_raises_and_writes_nothing(tmp_path):
    scene = raylab.default_scene()
    target = tmp_path / "missing" / "scene.json"
    with pytest.raises(raylab.SaveError, match="scene.json"):
        scene.save(str(target))
    assert not target.exists()


def test12_parse_names_its_origin_in_messages():
    with pytest.raises(raylab.SceneError, match="^lesson-scene: "):
        raylab.Scene.parse('{"raylab_scene": 2, "materials": [], "objects": 5}', "lesson-scene")


BAD = SOURCE_DIR / "tests" / "data" / "bad"


def test13_raw_bytes_in_a_message_are_escaped_as_on_the_command_line():
    # Issue 14: the JSON reader quotes the byte 0xff of a scene saved in another encoding;
    # the message holds it raw, which Python would refuse as UTF-8 (UnicodeDecodeError
    # instead of the SceneError). It reads \xff, as `raylab render` prints it.
    with pytest.raises(raylab.SceneError) as error:
        raylab.load_scene(str(BAD / "non-utf8-name.json"))
    message = str(error.value)
    assert "ill-formed UTF-8 byte" in message
    assert "last read: '\"ball\\xff'" in message
    message.encode("utf-8")  # valid text throughout


def test14_terminal_escape_bytes_in_a_message_are_escaped():
    # A name holding ESC [31m and BEL is quoted as \x1b[31m...\x07, never as controls.
    with pytest.raises(raylab.SceneError) as error:
        raylab.load_scene(str(BAD / "escape-name.json"))
    message = str(error.value)
    assert 'duplicate object "\\x1b[31mred\\x07"' in message
    assert "\x1b" not in message and "\x07" not in message


def test15_fresnel_plastic_and_priority_through_set_material():
    # Issue 37: the rates' Fresnel option, the plastic material and the nesting priority
    # are a material's values like any other, checked by the loader's rules.
    scene = raylab.default_scene()
    scene.set_material("red", fresnel="schlick", reflection_rate=1.0, refraction_rate=1.0)
    red = scene.materials[scene.material_names.index("red")]
    assert red["fresnel"] == "schlick"
    with pytest.raises(raylab.SceneError, match="reflection_rate \\+ refraction_rate"):
        scene.set_material("red", fresnel="none")
    scene.set_material("blue", type="plastic", roughness=0.2, ior=1.5, colour=[0.1, 0.2, 0.8])
    blue = scene.materials[scene.material_names.index("blue")]
    assert blue["type"] == "plastic" and blue["roughness"] == 0.2
    scene.set_material("red", reflection_rate=0.5, refraction_rate=0.5, type="dielectric",
                       fresnel="exact", priority=2)
    assert scene.materials[scene.material_names.index("red")]["priority"] == 2
    with pytest.raises(raylab.SceneError, match='fresnel "none" is for the rates'):
        scene.set_material("red", fresnel="none")
    scene.set_camera(width=16, height=12)
    image = raylab.render(scene, algorithm="path", spp=1)
    assert image.shape[:2] == (12, 16)


CHECKER_FLOOR = """{"raylab_scene": 2,
  "materials": [{"name": "floor", "type": "diffuse", "colour": [0.8, 0.8, 0.8],
                 "texture": {"type": "checker", "scale": 1, "colour2": [0.8, 0.1, 0.1]}}],
  "objects": [{"name": "floor", "material": "floor",
               "shape": {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}}],
  "point_lights": [{"name": "lamp", "position": [1, 3, 0.5], "intensity": [10, 10, 10]}],
  "camera": {"position": [1, 3, 0.5], "look_at": [1, 0, 0.5], "up": [0, 0, -1],
             "vertical_fov": 10, "width": 8, "height": 8},
  "render": {"background": [0, 0, 0]}}"""


def test16_checker_texture_made_read_set_and_rendered():
    # Issue 32: the checker texture is a material value like any other: made in a scene's
    # text, read back, set with set_material, checked by the loader's rules.
    scene = raylab.Scene.parse(CHECKER_FLOOR, "floor.json")
    texture = scene.materials[0]["texture"]
    assert texture == {"type": "checker", "scale": 1.0, "colour2": [0.8, 0.1, 0.1]}
    # The left half of the image sees the red cube, the right half the white one, under
    # every algorithm (linear values: the red pixel's red channel 8 times its green).
    for algorithm in ("raycast", "whitted", "distributed", "path"):
        image = raylab.render(scene, algorithm=algorithm, spp=1)
        red, white = image[4, 1], image[4, 6]
        assert red[0] / red[1] == pytest.approx(8.0, rel=1e-6), algorithm
        assert white[0] / white[1] == pytest.approx(1.0, rel=1e-6), algorithm
    scene.set_material("floor", texture={"type": "checker", "scale": 0.25})
    assert scene.get("/materials/0/texture/scale") == 0.25
    assert scene.get("/materials/0/texture/colour2") == [0.1, 0.1, 0.1]
    for bad, problem in ((0, "must be positive, got 0"), (-1, "must be positive, got -1"),
                         (float("nan"), "is not a JSON value")):
        with pytest.raises(raylab.SceneError, match="floor.json: at /materials/0/texture/scale") \
                as error:
            scene.set("/materials/0/texture/scale", bad)
        assert problem in str(error.value)
    with pytest.raises(raylab.SceneError, match="colour components must be in \\[0, 1\\]"):
        scene.set("/materials/0/texture/colour2", [0, 2, 0])
    with pytest.raises(raylab.SceneError, match='unknown key "size"'):
        scene.set("/materials/0/texture/size", 1)
    assert scene.get("/materials/0/texture/scale") == 0.25
