"""Ctrl-C (SIGINT) interrupts a long frames() loop between two steps with KeyboardInterrupt; the simulation stays at
the last frame handed out and continues from it with the same numbers as a run never interrupted. The steps run
without Python's lock: other threads go on meanwhile (a timer thread sends the signal here)."""
import os
import signal
import threading
import time

import pytest
import softbody

# One frame per simulated second of 100 000 steps of 1e-5 s: about 2 s of stepping per frame on one core.
LONG_FRAMES = {"fps": 1, "duration": 1000.0, "solver.dt": 1e-5}
# A million steps per frame (the most a frame may have): one frame takes far longer than any test waits.
ENDLESS_FRAME = {"fps": 1, "duration": 1000.0, "solver.dt": 1e-6}


def step_to(sim, index):
    for frame in sim.frames():
        if frame.index == index:
            return


def test_sigint_from_a_timer_thread_stops_frames_between_steps():
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set=LONG_FRAMES))
    frames = iter(sim.frames())
    next(frames)  # frame 0, no steps
    sent = []

    def interrupt():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(0.5, interrupt)
    started = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            for _ in frames:
                pass
    finally:
        timer.cancel()
    raised = time.monotonic()
    stopped_at = sim.frame.index

    # The frame in progress was dropped and the state put back: the next frame equals an uninterrupted run's.
    frame_started = time.monotonic()
    next(frames)
    frame_s = time.monotonic() - frame_started
    fresh = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set=LONG_FRAMES))
    step_to(fresh, stopped_at + 1)
    assert sim.frame.index == stopped_at + 1 and sim.row(0) == fresh.row(0)

    # The timer thread ran while the module stepped (on time, not when a frame ended), and the interrupt came
    # within the module's signal check (20 ms) and one step: well inside a frame.
    assert sent and sent[0] - started < 0.5 + frame_s / 2, "the timer thread did not run while the module stepped"
    assert raised - sent[0] < min(0.2, frame_s / 2), f"KeyboardInterrupt {raised - sent[0]:.3f} s after SIGINT, " \
                                                     f"a frame takes {frame_s:.3f} s"


def test_other_threads_may_not_use_a_simulation_while_it_steps():
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set=ENDLESS_FRAME))
    frames = iter(sim.frames())
    next(frames)
    errors = []

    def read_while_stepping():
        time.sleep(0.2)
        for read in (lambda: sim.row(0), lambda: sim.positions(0), lambda: softbody.render(sim, width=8, height=8)):
            try:
                read()
            except RuntimeError as error:
                errors.append(str(error))
        os.kill(os.getpid(), signal.SIGINT)  # ends the frame

    reader = threading.Thread(target=read_while_stepping)
    reader.start()
    with pytest.raises(KeyboardInterrupt):
        next(frames)
    reader.join()
    assert len(errors) == 3 and all("busy in another thread" in error for error in errors), errors
    assert sim.row(0)["frame"] == 0  # once the frame is dropped, it may


def test_sigint_stops_the_framing_pass_of_render():
    # scenes/roll.json has no camera: the first render() steps through the whole run (here 1000 s) to frame it.
    scene = softbody.load_scene("scenes/roll.json", set={"duration": 1000.0})
    sim = softbody.Simulation(scene)
    next(iter(sim.frames()))
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    started = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            softbody.render(sim, width=32, height=24)
    finally:
        timer.cancel()
    assert time.monotonic() - started < 2.0
    # The simulation is where it was.
    assert sim.frame.index == 0 and sim.row(0) == softbody.Simulation(scene).row(0)
