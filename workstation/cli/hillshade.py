"""`ws hillshade DEM.tif -o OUT.tif`: shaded relief (and slope/aspect) of a DEM."""

from __future__ import annotations

import click

from workstation.raster.terrain import PRODUCTS, HillshadeParams

from .options import emit_json, json_option, output_option, overwrite_option
from .options import GEOTIFF, require_suffix
from .options import FiniteFloatRange, positive_float
from .options import RegistryChoice, bound, param_group


@click.command()
@click.argument("dem", type=click.Path(exists=True, dir_okay=False))
@output_option
@param_group(
    "light",
    bound(HillshadeParams, "azimuth", "--azimuth", show_default=True, type=FiniteFloatRange(0.0, 360.0),
          help="Light direction, degrees clockwise from north."),
    bound(HillshadeParams, "altitude", "--altitude", show_default=True, type=FiniteFloatRange(0.0, 90.0),
          help="Light elevation above the horizon, degrees."),
    bound(HillshadeParams, "z_factor", "--z-factor", show_default=True, type=positive_float,
          help="Vertical exaggeration (dimensionless); heights in another unit than the cells "
               "(feet on metres) are converted on top of it."),
)
@click.option("--product", type=RegistryChoice(PRODUCTS), default=PRODUCTS[0], show_default=True,
              help="hillshade (0-255), slope (degrees) or aspect (degrees from north).")
@click.option("--png", type=click.Path(dir_okay=False), default=None, help="Also write a PNG preview of the result.")
@overwrite_option
@json_option
def hillshade(dem, output, light, product, png, overwrite, as_json):
    """Hillshade, slope or aspect of DEM by Horn (1981) gradients, as a GeoTIFF."""
    from workstation.io import atomic_paths, check_outputs
    from workstation.io.geotiff import read_raster, write_raster
    from workstation.raster import terrain

    require_suffix(output, GEOTIFF, what="GeoTIFF")
    require_suffix(png, (".png",), "--png", "PNG")
    check_outputs([output, png], overwrite, inputs=[dem])
    r = read_raster(dem, band=1)
    if product == "hillshade":
        out = terrain.hillshade(r, HillshadeParams(**light))
    elif product == "slope":
        out = terrain.slope(r, light["z_factor"])
    else:
        out = terrain.aspect(r)
    if not png:
        write_raster(out, output, overwrite=overwrite, inputs=[dem])
    else:  # both files or neither
        with atomic_paths([output, png], overwrite, inputs=[dem]) as (tif_tmp, png_tmp):
            write_raster(out, tif_tmp, overwrite=True)
            _write_png(out.array, product, png_tmp)
    from workstation.cli.summary import emit_summary

    emit_summary("hillshade", f"{product} {out.shape[0]:,} x {out.shape[1]:,} cells", [output, png])
    if as_json:
        emit_json({"output": output, "product": product, "rows": out.shape[0], "cols": out.shape[1], **out.meta})


#: A PNG preview is at least this many pixels on its long side (small rasters are upsampled).
PREVIEW_MIN_PX = 800


def preview_image(array, product: str, min_px: int = PREVIEW_MIN_PX):
    """(rows, cols) uint8 preview: the hillshade as is, slope and aspect stretched between
    percentiles 1-99; a raster smaller than ``min_px`` on its long side is enlarged by a whole
    factor (bilinear; nearest for aspect, whose degrees wrap), a larger one kept cell for pixel."""
    import cv2
    import numpy as np

    a = np.asarray(array, float)
    if product != "hillshade":
        lo, hi = np.nanpercentile(a, [1, 99])
        a = np.nan_to_num((a - lo) / max(hi - lo, 1e-9) * 255, nan=0)
    img = np.clip(np.nan_to_num(a, nan=0), 0, 255).astype(np.uint8)
    factor = int(np.ceil(min_px / max(img.shape)))
    if factor > 1:
        interp = cv2.INTER_NEAREST if product == "aspect" else cv2.INTER_LINEAR
        img = cv2.resize(img, (img.shape[1] * factor, img.shape[0] * factor), interpolation=interp)
    return img


def _write_png(array, product: str, path) -> None:
    """Write :func:`preview_image` as a PNG."""
    import cv2

    if not cv2.imwrite(str(path), preview_image(array, product)):
        raise OSError(f"OpenCV could not write the PNG {path}")
