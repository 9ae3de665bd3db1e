"""The geometric stage through the Python API: untangle="auto" (default)
untangles the inverted quads of a noisy map, untangle="off" keeps them,
smooth=N optimises every quad, strict refuses inverted quads left, bad
values are ValueErrors naming the argument; stats["geometry"] has the
CLI's keys."""

import numpy as np
import pytest

import dualex
from maps import cube, noisy_grid, square

SUMMARY_KEYS = {"elements", "inverted", "degenerate", "min", "p5", "median"}


def test_default_untangles_what_off_keeps():
    Q, quads, stats = dualex.quad(*noisy_grid())
    Qo, quads_o, stats_o = dualex.quad(*noisy_grid(), untangle="off")
    g, go = stats["geometry"], stats_o["geometry"]
    # the same extraction, the same quality before
    assert np.array_equal(quads, quads_o)
    assert g["before"] == go["before"]
    assert g["before"]["elements"] == len(quads) == 64
    assert go["before"]["inverted"] > 0
    # off: measured only
    assert go["mode"] == "off" and go["moved_vertices"] == 0
    assert go["after"] == go["before"]
    # auto: all untangled, by moving some vertices
    assert g["mode"] == "auto"
    assert g["after"]["inverted"] == 0 and g["after"]["min"] > 0
    moved = int(np.any(Q != Qo, axis=1).sum())
    assert moved == g["moved_vertices"] > 0


def test_geometry_has_the_cli_keys():
    _, _, stats = dualex.quad(*square(3))
    g = stats["geometry"]
    assert {"mode", "measure", "before", "after", "moved_vertices", "max_move", "max_move_edges",
            "mean_edge", "boundary", "rounds", "rings"} <= set(g)
    # its time is with the other stages' (as the CLI's stats)
    assert stats["time_ms"]["geometry"] >= 0
    assert set(g["before"]) == set(g["after"]) == SUMMARY_KEYS
    assert g["measure"] == "scaled Jacobian"
    # a clean grid of squares: nothing to do
    assert (g["before"]["inverted"], g["after"]["inverted"], g["moved_vertices"]) == (0, 0, 0)
    assert g["after"]["min"] == pytest.approx(1.0)
    _, _, stats = dualex.hex(*cube(2))
    assert stats["geometry"]["before"]["elements"] == 8
    assert stats["geometry"]["after"]["inverted"] == 0


def test_smooth_raises_the_low_percentile():
    _, _, stats = dualex.quad(*noisy_grid(), smooth=5)
    g = stats["geometry"]
    assert g["mode"] == "smooth"
    assert 1 <= g["rounds"] <= 5
    assert g["after"]["p5"] >= g["before"]["p5"]
    assert g["after"]["inverted"] == 0
    # True: the default rounds; False: no smoothing
    _, _, stats = dualex.quad(*noisy_grid(), smooth=True)
    assert stats["geometry"]["mode"] == "smooth"
    _, _, stats = dualex.quad(*noisy_grid(), smooth=False)
    assert stats["geometry"]["mode"] == "auto"
    _, _, stats = dualex.hex(*cube(2), smooth=2)
    assert stats["geometry"]["mode"] == "smooth"
    assert stats["geometry"]["after"]["inverted"] == 0


def test_strict_refuses_inverted_quads_left():
    _, _, stats = dualex.quad(*noisy_grid(), untangle="off")
    left = stats["geometry"]["after"]["inverted"]
    with pytest.raises(ValueError, match=f"^{left} inverted elements .* remain after the geometric stage"):
        dualex.quad(*noisy_grid(), untangle="off", strict=True)
    _, _, stats = dualex.quad(*noisy_grid(), strict=True)
    assert stats["geometry"]["after"]["inverted"] == 0


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"untangle": "on"}, "^untangle: expected \"auto\" or \"off\", got 'on'$"),
        ({"untangle": 1}, "^untangle: expected"),
        ({"smooth": 0}, "^smooth: expected None, True or a number of rounds >= 1, got 0$"),
        ({"smooth": -3}, "^smooth: expected"),
        ({"smooth": 2.5}, "^smooth: expected"),
        ({"smooth": "5"}, "^smooth: expected"),
        ({"smooth": 5, "untangle": "off"}, "^smooth: smoothing moves the vertices"),
    ],
)
def test_bad_values_name_the_argument(kwargs, message):
    with pytest.raises(ValueError, match=message):
        dualex.quad(*square(2), **kwargs)
    with pytest.raises(ValueError, match=message):
        dualex.hex(*cube(2), **kwargs)
