import numpy as np
import pytest

from workstation.core import ASPRSClass, Cloud, InvalidInputError, canonical_name, class_name, concatenate
from workstation.core.classes import CLASS_NAMES
from workstation.core.dims import DIMS


def test_arrays_are_read_only_and_input_untouched():
    xyz = np.zeros((4, 3))
    inten = np.arange(4)
    c = Cloud(xyz, {"intensity": inten})
    with pytest.raises(ValueError):
        c.xyz[0, 0] = 1
    with pytest.raises(ValueError):
        c.attrs["intensity"][0] = 9
    with pytest.raises(TypeError):
        c.attrs["new"] = np.zeros(4)
    xyz[0, 0] = 5  # the caller's array stays writeable
    assert inten.flags.writeable


def test_known_dims_cast_to_table_dtype():
    c = Cloud(np.zeros((2, 3)), {"classification": [2, 6], "rgb": [[1, 2, 3], [4, 5, 6]], "hag": [0.5, 1.5]})
    assert c.attrs["classification"].dtype == np.uint8
    assert c.attrs["rgb"].dtype == np.uint16 and c.attrs["rgb"].shape == (2, 3)
    assert c.attrs["hag"].dtype == np.float32


@pytest.mark.parametrize(
    "attrs, field",
    [
        ({"intensity": [1, 2, 3]}, "intensity"),  # wrong length
        ({"classification": [2, 300]}, "classification"),  # out of u8 range
        ({"intensity": [1.5, 2.0]}, "intensity"),  # fractional into an integer dim
        ({"rgb": [1, 2]}, "rgb"),  # wrong per-point shape
    ],
)
def test_bad_attributes_name_the_field(attrs, field):
    with pytest.raises(InvalidInputError) as e:
        Cloud(np.zeros((2, 3)), attrs)
    assert e.value.field == field
    assert field in str(e.value)


def test_nan_coordinates_rejected_with_index():
    xyz = np.zeros((5, 3))
    xyz[3, 1] = np.nan
    with pytest.raises(InvalidInputError, match="index 3"):
        Cloud(xyz)
    with pytest.raises(InvalidInputError):
        Cloud(np.zeros((5, 2)))


def test_selection_keeps_every_attribute(small_cloud):
    mask = small_cloud.attrs["classification"] == ASPRSClass.GROUND
    sub = small_cloud[mask]
    assert sub.n == int(mask.sum())
    assert sub.dims == small_cloud.dims
    np.testing.assert_array_equal(sub.attrs["gps_time"], small_cloud.attrs["gps_time"][mask])
    idx = np.array([5, 1, 5])
    sub2 = small_cloud[idx]
    np.testing.assert_array_equal(sub2.xyz, small_cloud.xyz[idx])
    assert sub2.crs == small_cloud.crs
    with pytest.raises(InvalidInputError):
        small_cloud[np.array([small_cloud.n])]
    with pytest.raises(InvalidInputError):
        small_cloud[np.ones(3, bool)]


def test_with_attrs_returns_new_cloud(small_cloud):
    c2 = small_cloud.with_attrs(hag=np.ones(small_cloud.n))
    assert "hag" in c2 and "hag" not in small_cloud
    c3 = c2.without_attrs("hag", "intensity")
    assert "intensity" not in c3 and "intensity" in c2
    c4 = c3.with_history("test", {"a": 1})
    assert c4.history[-1].stage == "test" and not c3.history


def test_concatenate_union_of_attributes_and_crs_check():
    a = Cloud(np.zeros((2, 3)), {"intensity": [5, 6], "feat": np.array([0.5, 0.25])}, crs="EPSG:32632")
    b = Cloud(np.ones((3, 3)), {"classification": [2, 2, 6], "rgb": np.full((3, 3), 7)})
    c = concatenate([a, b])
    assert c.n == 5 and c.crs == "EPSG:32632"
    assert c.attrs["intensity"].tolist() == [5, 6, 0, 0, 0]
    assert c.attrs["classification"].tolist() == [0, 0, 2, 2, 6]
    assert c.attrs["rgb"].shape == (5, 3) and c.attrs["rgb"][:2].sum() == 0
    assert np.isnan(c.attrs["feat"][2:]).all() and c.attrs["feat"][0] == 0.5
    other = Cloud(np.ones((1, 3)), crs="EPSG:4326")
    with pytest.raises(InvalidInputError, match="CRS"):
        concatenate([a, other])


def test_asprs_classes_complete():
    assert [int(c) for c in ASPRSClass] == list(range(23))
    assert set(CLASS_NAMES) == set(range(23))
    assert ASPRSClass.BRIDGE_DECK == 17 and ASPRSClass.WATER == 9
    assert class_name(6) == "Building" and "Reserved" in class_name(40) and "User" in class_name(65)


def test_dims_aliases():
    assert canonical_name("Classification") == "classification"
    assert canonical_name("GpsTime") == "gps_time"
    assert canonical_name("normals") == "normal"
    assert canonical_name("Deviation") == "Deviation"
    assert all(d.dtype.kind in "uif" for d in DIMS.values())
