"""Simulation.row() gives the CSV's numbers bit for bit: every row of `softbody simulate --csv -`, frame 0 first."""
import softbody

from conftest import set_arguments


def program_rows(program, scene, overrides):
    """The program's CSV: its header's column names and its rows as lists of strings."""
    text = program.run("simulate", scene, *set_arguments(overrides), "--csv", "-").stdout
    lines = text.splitlines()
    return lines[0].split(","), [line.split(",") for line in lines[1:]]


def module_rows(scene, overrides):
    """The same run through the module: the rows of every body at every frame, as dicts."""
    sim = softbody.Simulation(softbody.load_scene(scene, set=overrides))
    rows = []
    for frame in sim.frames():
        for body in range(sim.body_count):
            row = sim.row(body)
            assert (row["frame"], row["time"], row["body"]) == (frame.index, frame.time, body)
            rows.append(row)
    return rows


def assert_same_rows(program, scene, overrides):
    columns, expected = program_rows(program, scene, overrides)
    actual = module_rows(scene, overrides)
    assert len(actual) == len(expected)
    for got, want in zip(actual, expected):
        assert list(got) == columns
        # %.17g (the program's format) reads back as the very double: equal means the same bits.
        assert int(want[0]) == got["frame"] and int(want[2]) == got["body"]
        for name, text in zip(columns, want):
            assert float(text) == got[name], f"frame {got['frame']}, body {got['body']}, {name}"
    return actual


def test_bounce_rows_equal_the_programs_csv(program):
    rows = assert_same_rows(program, "scenes/bounce.json", {"duration": 0.5})
    assert len(rows) == 16  # frame 0 and 15 frames at 30 fps


def test_pile_rows_equal_the_programs_csv(program):
    # Four bodies (three pillows from a mesh file and a ball), contact between bodies.
    rows = assert_same_rows(program, "scenes/pile.json", {"duration": 0.2})
    assert {row["body"] for row in rows} == {0, 1, 2, 3}


def test_positions_are_a_copy_of_the_vertices():
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set={"duration": 0.1}))
    frames = iter(sim.frames())
    assert next(frames).index == 0
    x = sim.positions(0)
    assert x.shape == (642, 3) and x.dtype.name == "float64"
    # The ball starts centred at (0, 3, 0) with unit radius.
    assert abs(x[:, 1].min() - 2.0) < 1e-12 and abs(x[:, 1].max() - 4.0) < 1e-12
    x[:] = 0.0  # a copy: the simulation is untouched
    assert sim.positions(0)[:, 1].max() > 3.9
    next(frames)
    assert sim.positions(0)[:, 0].mean() > 0.0  # thrown sideways at 2 m/s
