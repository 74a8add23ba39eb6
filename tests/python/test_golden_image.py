"""A golden-image test as a user writes one: render a frame, compare it with a stored PNG within a tolerance.

SOFTBODY_UPDATE_GOLDEN=1 writes the reference anew (check the picture before committing it). On failure the
differing pixels are written beside the test's scratch folder as a diff image."""
import os
import pathlib

import numpy as np
import softbody

GOLDEN = pathlib.Path(__file__).parent / "golden" / "bounce_landing.png"
CHANNEL_THRESHOLD = 16   # 8-bit levels: rasterisation may differ at edges between GL drivers and versions
ALLOWED_FRACTION = 0.01  # of the pixels


def render_landing():
    # The ball on the floor, squashed, at 0.7 s (frame 21 at 30 fps).
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set={"duration": 0.7}))
    for frame in sim.frames():
        if frame.index == 21:
            return softbody.render(sim, width=200, height=150)


def test_bounce_landing_matches_the_golden_image(tmp_path):
    image = render_landing()
    if os.environ.get("SOFTBODY_UPDATE_GOLDEN") == "1":
        softbody.write_png(GOLDEN, image)
    expected = softbody.read_png(GOLDEN)
    assert image.shape == expected.shape
    assert image.std() > 10, "a blank picture"
    differs = np.abs(image.astype(int) - expected.astype(int)).max(axis=2) > CHANNEL_THRESHOLD
    if differs.mean() > ALLOWED_FRACTION:
        diff = np.where(differs[..., None], [255, 0, 255], image // 3).astype(np.uint8)
        softbody.write_png(tmp_path / "diff.png", diff)
        raise AssertionError(f"{differs.mean():.2%} of the pixels differ by more than {CHANNEL_THRESHOLD} levels "
                             f"(allowed {ALLOWED_FRACTION:.0%}); diff image: {tmp_path / 'diff.png'}")


def test_frames_differ():
    sim = softbody.Simulation(softbody.load_scene("scenes/bounce.json", set={"duration": 0.2}))
    frames = iter(sim.frames())
    next(frames)
    first = softbody.render(sim, width=80, height=60)
    for _ in frames:
        pass
    assert not np.array_equal(first, softbody.render(sim, width=80, height=60))
