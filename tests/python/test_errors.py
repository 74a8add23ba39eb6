"""Bad input raises softbody.SceneError and a diverged run softbody.DivergedError, with the program's messages."""
import pytest
import softbody

from conftest import set_arguments


def program_message(program, scene, overrides, status):
    """The program's one-line message on standard error for a run that exits `status`, without its prefix."""
    result = program.run("simulate", scene, *set_arguments(overrides), "--csv", "-", check=False)
    assert result.returncode == status, result.stderr
    last = result.stderr.strip().splitlines()[-1]
    prefix = {2: "error: ", 3: "diverged: "}[status]
    assert last.startswith(prefix)
    return last[len(prefix):]


def test_misspelt_key_is_a_scene_error_with_the_programs_message(program):
    overrides = {"bodies.0.stifness": 800}
    with pytest.raises(softbody.SceneError) as error:
        softbody.load_scene("scenes/bounce.json", set=overrides)
    assert str(error.value) == program_message(program, "scenes/bounce.json", overrides, 2)
    assert "stifness" in str(error.value)
    assert isinstance(error.value, ValueError)


def test_bad_value_is_a_scene_error_with_the_programs_message(program):
    overrides = {"solver.integrator": "leapfrog"}  # a str value is read as --set reads it
    with pytest.raises(softbody.SceneError) as error:
        softbody.load_scene("scenes/bounce.json", set=overrides)
    assert str(error.value) == program_message(program, "scenes/bounce.json", overrides, 2)


def test_missing_scene_file_is_a_scene_error(program):
    with pytest.raises(softbody.SceneError) as error:
        softbody.load_scene("scenes/no_such_scene.json")
    assert str(error.value) == program_message(program, "scenes/no_such_scene.json", {}, 2)


def test_divergence_raises_with_the_programs_message_after_the_frames_before(program):
    # Far beyond forward Euler's stable step for this stiffness: blows up within a few frames.
    overrides = {"bodies.0.stiffness": 1e6, "solver.dt": 1e-3}
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set=overrides))
    handed_out = []
    with pytest.raises(softbody.DivergedError) as error:
        for frame in sim.frames():
            handed_out.append(frame.index)
    assert str(error.value) == program_message(program, "scenes/bounce.json", overrides, 3)
    assert handed_out == list(range(len(handed_out))) and handed_out[0] == 0
    # The simulation stays at the last frame handed out, whose numbers are finite, and says so again.
    assert sim.frame.index == handed_out[-1]
    assert all(value == value for value in sim.row(0).values())
    with pytest.raises(softbody.DivergedError):
        next(iter(sim.frames()))


def test_body_out_of_range_is_an_index_error():
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set={"duration": 0.1}))
    with pytest.raises(IndexError, match="body 1"):
        sim.positions(1)
    with pytest.raises(IndexError):
        sim.row(-1)
