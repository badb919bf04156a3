"""The shared helpers of core: colour scaling (core.color), the local origin and the
similarity fit (core.geometry), and that every interop module uses the same ones."""

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.color import rgb_to_u8, rgb_to_unit, unit_to_rgb16
from workstation.core.errors import InvalidInputError
from workstation.core.geometry import default_origin, umeyama


def _rot(rng):
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return q * np.sign(np.linalg.det(q))


def test_16bit_array_holding_8bit_values_scales_like_8bit(rng):
    """The colour bug: u16 colours with 8-bit values were near-black for coloured ICP (divided
    by 65535) and correct for MeshLab (divided by 255); now every path divides by 255."""
    c8 = rng.integers(0, 256, (200, 3)).astype(np.uint8)
    c8[0] = [255, 0, 128]  # the top of the 8-bit range is present
    want = c8 / 255.0
    assert np.array_equal(rgb_to_unit(c8), want)
    assert np.array_equal(rgb_to_unit(c8.astype(np.uint16)), want)
    assert np.array_equal(rgb_to_unit(c8.astype(np.int32)), want)
    # the coloured-ICP path (registration) and the MeshLab path agree with it
    from workstation.interop import open3d as io3d
    from workstation.interop import pymeshlab as iml
    from workstation.registration.register import _colors

    assert io3d.rgb_to_unit is rgb_to_unit and iml.rgb_to_unit is rgb_to_unit
    cloud16 = Cloud(rng.normal(size=(200, 3)), {"rgb": c8.astype(np.uint16)})
    assert np.array_equal(_colors(cloud16), want)
    pytest.importorskip("open3d")
    pcd, _ = io3d.to_legacy(cloud16)
    np.testing.assert_allclose(np.asarray(pcd.colors), want)
    t, _ = io3d.to_tensor(cloud16, dtype="float64")
    np.testing.assert_allclose(t.point.colors.numpy(), want)


def test_16bit_and_float_colours():
    full = np.array([[65535, 0, 13107], [256, 0, 0]], np.uint16)  # a value above 255: 16-bit
    np.testing.assert_allclose(rgb_to_unit(full), full / 65535.0)
    assert rgb_to_unit(np.array([[-0.5, 0.25, 2.0]])).tolist() == [[0.0, 0.25, 1.0]]
    assert rgb_to_unit(np.zeros((0, 3), np.uint16)).shape == (0, 3)
    assert rgb_to_u8(full).tolist() == [[255, 0, 51], [1, 0, 0]]
    assert rgb_to_u8(np.array([[255, 128, 0]], np.uint16)).tolist() == [[255, 128, 0]]
    assert unit_to_rgb16(np.array([[1.0, 0.2, -1.0]])).tolist() == [[65535, 13107, 0]]
    assert np.array_equal(unit_to_rgb16(rgb_to_unit(full)), full)


def test_default_origin_is_the_rounded_box_centre_and_shared(rng):
    xyz = rng.uniform(0, 100, (500, 3)) + [500_000.0, 5_000_000.0, 300.0]
    o = default_origin(xyz)
    assert o.dtype == np.float64 and o.shape == (3,)
    assert np.array_equal(o, np.round(0.5 * (xyz.min(axis=0) + xyz.max(axis=0))))
    assert np.array_equal(o, np.round(o)) and np.all(np.abs(o - xyz.mean(axis=0)) < 60)
    assert default_origin(np.zeros((0, 3))).tolist() == [0.0, 0.0, 0.0]
    assert default_origin([[1.4, 2.6, -3.5]]).tolist() == [1.0, 3.0, -4.0]
    from workstation.interop import open3d, pymeshlab, pyvista

    assert open3d.default_origin is pymeshlab.default_origin is pyvista.default_origin is default_origin


@pytest.mark.parametrize("with_scale", [False, True])
def test_umeyama_recovers_a_similarity(rng, with_scale):
    src = rng.normal(size=(30, 3)) * 10
    R, t, s = _rot(rng), rng.normal(size=3) * 100, (2.5 if with_scale else 1.0)
    dst = s * src @ R.T + t
    Re, te, se = umeyama(src, dst, with_scale=with_scale)
    np.testing.assert_allclose(Re, R, atol=1e-10)
    np.testing.assert_allclose(te, t, atol=1e-8)
    assert se == pytest.approx(s, abs=1e-12)
    assert np.linalg.det(Re) == pytest.approx(1.0)
    # weights: a gross outlier with zero weight changes nothing
    bad = dst.copy()
    bad[0] += 1000.0
    w = np.ones(len(src))
    w[0] = 0.0
    Rw, tw, sw = umeyama(src, bad, w, with_scale)
    np.testing.assert_allclose(Rw, R, atol=1e-10)
    np.testing.assert_allclose(tw, t, atol=1e-8)
    from workstation.registration import transforms

    assert transforms.umeyama is umeyama


def test_umeyama_refuses_bad_input(rng):
    with pytest.raises(InvalidInputError):
        umeyama(rng.normal(size=(2, 3)), rng.normal(size=(2, 3)))
    with pytest.raises(InvalidInputError):
        umeyama(rng.normal(size=(4, 3)), rng.normal(size=(5, 3)))
    with pytest.raises(InvalidInputError):
        umeyama(rng.normal(size=(4, 3)), rng.normal(size=(4, 3)), np.zeros(4))
