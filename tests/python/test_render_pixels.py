"""softbody.render() draws the pixels `softbody render` writes, on the same GL backend, with the same camera: the
scene's, or where it has none the camera the program frames the whole run with."""
import numpy as np
import softbody

from conftest import set_arguments

SIZE = {"render.width": 160, "render.height": 120, "render.figure_frames": 0}


def program_frame(program, tmp_path, scene, overrides, index):
    program.run("render", scene, *set_arguments({**overrides, **SIZE}), "-o", tmp_path)
    return softbody.read_png(tmp_path / f"frame_{index:04d}.png")


def module_frame(scene, overrides, index):
    sim = softbody.Simulation(softbody.load_scene(scene, set=overrides))
    for frame in sim.frames():
        if frame.index == index:
            return softbody.render(sim, width=160, height=120)
    raise AssertionError(f"no frame {index}")


def test_bounce_frame_equals_the_programs_png(tmp_path, program):
    overrides = {"duration": 0.4}
    expected = program_frame(program, tmp_path, "scenes/bounce.json", overrides, 12)
    actual = module_frame("scenes/bounce.json", overrides, 12)
    assert actual.shape == (120, 160, 3) and actual.dtype == np.uint8
    assert np.array_equal(actual, expected)


def test_framing_camera_equals_the_programs(tmp_path, program):
    # scenes/roll.json has no camera: both frame the box the body sweeps over the whole run, after a silent pass.
    overrides = {"duration": 0.4}
    expected = program_frame(program, tmp_path, "scenes/roll.json", overrides, 7)  # 25 fps: 0.28 s
    actual = module_frame("scenes/roll.json", overrides, 7)
    assert np.array_equal(actual, expected)


def test_size_defaults_to_the_scenes():
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set={"duration": 0.1, **SIZE}))
    next(iter(sim.frames()))
    assert softbody.render(sim).shape == (120, 160, 3)
