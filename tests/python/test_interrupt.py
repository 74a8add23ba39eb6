"""Ctrl-C (SIGINT) interrupts a long frames() loop between two steps with KeyboardInterrupt; the simulation stays at
the last frame handed out and continues from it with the same numbers as a run never interrupted."""
import os
import signal
import threading
import time

import pytest
import softbody

# One frame per simulated second: 10 000 steps of 1e-4 s each, so that the signal arrives while the module steps.
LONG_FRAMES = {"fps": 1, "duration": 1000.0}


def test_sigint_stops_frames_between_steps():
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set=LONG_FRAMES))
    frames = iter(sim.frames())
    next(frames)  # frame 0, no steps
    sent = []

    def interrupt():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(0.5, interrupt)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            for _ in frames:
                pass
    finally:
        timer.cancel()
    raised = time.monotonic()
    # Within one step, not at the end of a frame (a frame takes far longer than this here).
    assert raised - sent[0] < 0.2, f"KeyboardInterrupt {raised - sent[0]:.3f} s after SIGINT"
    stopped_at = sim.frame.index
    assert stopped_at < sim.last_frame

    # The frame in progress was dropped: the next one equals an uninterrupted run's.
    next(frames)
    assert sim.frame.index == stopped_at + 1
    fresh = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set=LONG_FRAMES))
    for frame in fresh.frames():
        if frame.index == stopped_at + 1:
            break
    assert sim.row(0) == fresh.row(0)
