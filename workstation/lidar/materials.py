"""The material table shared by the LiDAR simulator and the photo renderer.

Every scene triangle carries a material id, an index into :data:`MATERIALS`. A material gives
the diffuse (Lambertian) reflectance at the two common laser wavelengths, a specular lobe
for mirror-like surfaces (water), an albedo colour and a procedural texture id for photos.

Reflectances are hemispherical values in [0, 1], typical of the spectral libraries
(ASTER / ECOSTRESS spectral library, Baldridge et al. 2009, Remote Sensing of Environment
113(4):711-715; Meerdink et al. 2019): green vegetation is bright in the near infrared at
1064 nm and darker at 1550 nm where leaf water absorbs; asphalt is dark at both; water
reflects almost nothing diffusely and returns energy only near specular incidence.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError

# Procedural texture ids the photo renderer understands (0 = flat albedo colour).
TEXTURES: dict[int, str] = {
    0: "flat",
    1: "grass",
    2: "soil",
    3: "asphalt",
    4: "brick",
    5: "roof_tiles",
    6: "stone",
    7: "bark",
    8: "leaves",
    9: "water",
    10: "metal",
    11: "gravel",
    12: "concrete",
}


@dataclass(frozen=True)
class Material:
    """One surface material.

    Attributes
    ----------
    id : int
        Index in the table (the per-triangle ``material`` attribute).
    name : str
    reflectance_1064, reflectance_1550 : float
        Diffuse Lambertian reflectance (0-1) at 1064 nm and 1550 nm.
    specular : float
        Strength (0-1) of a Gaussian specular lobe around normal incidence.
    specular_width_deg : float
        Width (1-sigma, degrees of incidence angle) of that lobe.
    albedo : tuple of 3 int
        Visible colour (sRGB 0-255) for photos and point colours.
    texture : int
        Procedural texture id (key of :data:`TEXTURES`).
    porosity : float
        Probability (0-1) that a ray meeting a triangle of this material passes on through
        gaps smaller than the triangle (foliage: leaves and needles are far smaller than the
        leaf-cluster triangles that stand for them).
    """

    id: int
    name: str
    reflectance_1064: float
    reflectance_1550: float
    specular: float = 0.0
    specular_width_deg: float = 3.0
    albedo: tuple = (128, 128, 128)
    texture: int = 0
    porosity: float = 0.0

    def reflectance(self, wavelength_nm: float) -> float:
        """Diffuse reflectance at a wavelength, interpolated linearly between 1064 and 1550 nm."""
        return float(np.interp(wavelength_nm, [1064.0, 1550.0], [self.reflectance_1064, self.reflectance_1550]))


_M = Material
MATERIALS: tuple[Material, ...] = (
    _M(0, "grass", 0.45, 0.28, albedo=(92, 140, 60), texture=1),
    _M(1, "soil", 0.28, 0.36, albedo=(130, 100, 70), texture=2),
    _M(2, "gravel", 0.30, 0.34, albedo=(150, 145, 135), texture=11),
    _M(3, "asphalt", 0.09, 0.11, albedo=(70, 70, 72), texture=3),
    _M(4, "concrete", 0.35, 0.38, albedo=(185, 182, 175), texture=12),
    _M(5, "brick", 0.42, 0.45, albedo=(165, 80, 60), texture=4),
    _M(6, "roof_tiles", 0.45, 0.50, albedo=(170, 70, 50), texture=5),
    _M(7, "roof_metal", 0.30, 0.28, specular=0.15, specular_width_deg=5.0, albedo=(95, 100, 110), texture=10),
    _M(8, "sandstone", 0.48, 0.52, albedo=(205, 185, 150), texture=6),
    _M(9, "bark", 0.35, 0.40, albedo=(90, 65, 45), texture=7),
    _M(10, "leaves", 0.50, 0.30, albedo=(60, 120, 45), texture=8, porosity=0.4),
    _M(11, "needles", 0.40, 0.22, albedo=(40, 85, 40), texture=8, porosity=0.4),
    _M(12, "shrub", 0.42, 0.26, albedo=(80, 125, 55), texture=8, porosity=0.3),
    _M(13, "water", 0.003, 0.001, specular=0.15, specular_width_deg=1.0, albedo=(45, 80, 110), texture=9),
    _M(14, "car_paint", 0.25, 0.22, specular=0.1, specular_width_deg=4.0, albedo=(150, 30, 30), texture=0),
    _M(15, "steel", 0.25, 0.20, albedo=(130, 130, 135), texture=10),
    _M(16, "plaster", 0.60, 0.55, albedo=(225, 215, 195), texture=0),
    _M(17, "rock", 0.32, 0.38, albedo=(120, 115, 105), texture=6),
    _M(18, "grass_blades", 0.45, 0.28, albedo=(105, 150, 65), texture=1, porosity=0.3),
)
MATERIAL_ID: dict[str, int] = {m.name: m.id for m in MATERIALS}


def material_arrays(wavelength_nm: float, materials=MATERIALS) -> dict[str, np.ndarray]:
    """Per-material lookup arrays for vectorised use.

    Returns
    -------
    dict
        ``reflectance`` (k,) f8 at ``wavelength_nm``, ``specular`` (k,) f8,
        ``specular_width`` (k,) f8 in radians, ``albedo`` (k, 3) u8, ``porosity`` (k,) f8.
    """
    if not 400.0 <= wavelength_nm <= 2000.0:
        raise InvalidInputError(f"wavelength {wavelength_nm} nm is outside 400-2000 nm", field="wavelength_nm")
    return {
        "reflectance": np.array([m.reflectance(wavelength_nm) for m in materials]),
        "specular": np.array([m.specular for m in materials]),
        "specular_width": np.radians([m.specular_width_deg for m in materials]),
        "albedo": np.array([m.albedo for m in materials], dtype=np.uint8),
        "porosity": np.array([m.porosity for m in materials]),
    }
