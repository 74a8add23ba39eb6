"""The module as installed and imported: its version, its frames, its scene."""
import softbody


def test_version_is_the_programs(program):
    version = program.run("--version").stdout
    assert softbody.__version__ and softbody.__version__ in version


def test_frames_start_at_zero_and_end_at_the_duration():
    scene = softbody.load_scene("scenes/bounce.json", set={"duration": 0.2})
    assert (scene.name, scene.fps, scene.duration) == ("bounce", 30, 0.2)
    sim = softbody.Simulation(scene)
    frames = [(frame.index, frame.time) for frame in sim.frames()]
    assert frames == [(i, i * (1.0 / 30)) for i in range(7)] and sim.last_frame == 6
    assert list(sim.frames()) == []  # at the end: nothing more
