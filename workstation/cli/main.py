"""The ``ws`` / ``workstation`` command group.

Commands are loaded lazily from the table below so ``ws --help`` starts fast; each lives in
its own module of this package. Every command runs inside one error boundary
(:func:`main`): deliberate errors become a message on stderr and exit code 1 (traceback with
``-v``), usage errors exit 2.
"""

from __future__ import annotations

import importlib
import sys

import click

from workstation.core.signals import Terminated

# command name -> (module:attribute, one-line help shown by `ws --help` without importing it)
COMMANDS: dict[str, tuple[str, str]] = {
    "info": ("workstation.cli.info:info", "Header, counts, bounds, dimensions, classes, density and CRS of a cloud."),
    "convert": ("workstation.cli.convert:convert", "Convert a cloud between formats; assign or reproject its CRS."),
    "register": ("workstation.cli.register:register", "Register a cloud onto another (global + ICP); write the moved source."),
    "crop": ("workstation.cli.crop:crop", "Keep the points inside (or outside) a box or polygons (GeoJSON, GeoPackage)."),
    "filter": ("workstation.cli.filter:filter_cmd", "Keep the points matching a PDAL expression (Classification == 2 && ...)."),
    "thin": ("workstation.cli.thin:thin", "Thin a cloud: one point per voxel, or Poisson-disk sampling."),
    "tile": ("workstation.cli.tile:tile", "Cut clouds into square tiles named by their lower-left corner (streamed)."),
    "merge": ("workstation.cli.merge:merge", "Merge registered clouds keeping every attribute; optional pose graph."),
    "colorize": ("workstation.cli.colorize:colorize", "Colour a cloud from oriented photos with occlusion tests."),
    "ground": ("workstation.cli.ground:ground", "Classify ground (2) and non-ground (1): SMRF, CSF, PMF, PTD, auto, baselines."),
    "evaluate": ("workstation.cli.evaluate:evaluate", "Confusion matrix, ISPRS Type I/II, total error and kappa against a reference."),
    "demo": ("workstation.cli.demo:demo", "Run every stage on a generated synthetic scene."),
    "mesh": ("workstation.cli.mesh:mesh", "Mesh a cloud (screened Poisson, ball pivoting, 2.5D Delaunay) with MeshLab filters."),
    "render": ("workstation.cli.render:render", "Render a cloud or mesh off-screen to PNG (or a turntable GIF)."),
    "report": ("workstation.cli.report:report", "Quality report of a work folder (HTML or PDF): summary, accuracies, QC verdict, figures."),
    "train": ("workstation.cli.train:train", "Train the point classifier on simulated LiDAR (recipe TOML)."),
    "classify": ("workstation.cli.classify:classify", "Classify points (ground, vegetation, building, water, other, noise)."),
    "simulate": ("workstation.cli.simulate:simulate", "Simulate ALS/ULS/MLS/TLS LiDAR of a labelled synthetic scene."),
    "plan-flight": ("workstation.cli.plan_flight:plan_flight", "Airborne LiDAR flight plan: swath, spacing, density, lines, time."),
    "dem": ("workstation.cli.dem:dem", "Grid clouds into a DSM, DTM or CHM GeoTIFF (TIN, natural neighbour, IDW, pit-free)."),
    "hillshade": ("workstation.cli.hillshade:hillshade", "Hillshade, slope or aspect of a DEM GeoTIFF."),
    "contours": ("workstation.cli.contours:contours", "Contour lines of a DEM as GeoJSON (index contours, smoothing)."),
    "ortho": ("workstation.cli.ortho:ortho", "True orthophoto from oriented images over a DSM."),
    "calibrate": ("workstation.cli.calibrate:calibrate", "Calibrate a camera (Zhang planar target or DLT) to CAMERA.json."),
    "sfm": ("workstation.cli.sfm:sfm", "Orient photos and build a sparse cloud (pycolmap); georeference with GCPs."),
    "run": ("workstation.cli.run:run", "Process a project (project.toml): every stage over every chunk, on a Dask cluster."),
    "qc": ("workstation.cli.qc:qc", "Check a LiDAR delivery against USGS QL0-QL3 or ASPRS classes: format, density, voids, swath DZ, NVA/VVA."),
    "publish": ("workstation.cli.publish:publish", "Publish products as a static web viewer (COPC streamed by level of detail, maps, cameras); --serve."),
    "strip-adjust": ("workstation.cli.strip_adjust:strip_adjust", "Boresight calibration and strip adjustment of overlapping ALS flight lines."),
    "buildings": ("workstation.cli.buildings:buildings", "Roof planes, footprints, LoD1.2/LoD2.2 models (CityJSON, glTF, OBJ) and rooftop solar potential (per face and a roof map)."),
    "dense": ("workstation.cli.dense:dense", "Dense cloud from an SfM workdir: depth maps (CPU semi-global matching or plane sweep, CUDA PatchMatch) and fusion."),
}


class LazyGroup(click.Group):
    """A click group that imports a command's module only when that command runs."""

    def list_commands(self, ctx):
        return sorted(COMMANDS)

    def get_command(self, ctx, name):
        if name not in COMMANDS:
            return None
        target, _ = COMMANDS[name]
        mod, attr = target.split(":")
        return getattr(importlib.import_module(mod), attr)

    def format_commands(self, ctx, formatter):
        rows = [(name, COMMANDS[name][1]) for name in self.list_commands(ctx)]
        with formatter.section("Commands"):
            formatter.write_dl(rows)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.option("-v", "--verbose", count=True, help="More log output on stderr (-vv for debug); tracebacks on errors.")
@click.option("-q", "--quiet", is_flag=True, help="Only errors on stderr.")
@click.version_option(package_name="workstation")
@click.pass_context
def cli(ctx, verbose, quiet):
    """workstation: point clouds, photogrammetry, LiDAR simulation, registration, DEMs and meshes.

    Products go to files, logs and progress to stderr, --json results to stdout.
    """
    from workstation.cli.summary import mark_start
    from workstation.core.log import configure

    mark_start()
    ctx.ensure_object(dict)
    ctx.obj["verbose"] = verbose
    configure(verbose, quiet)


def _on_signal(signum, frame):
    raise Terminated(signum)


def _install_signal_handlers() -> None:
    import signal
    import threading

    if threading.current_thread() is threading.main_thread():
        for sig in (signal.SIGTERM, signal.SIGHUP):
            signal.signal(sig, _on_signal)


def main(argv=None) -> int:
    """Entry point with the error boundary: exit 0 ok, 1 error (:mod:`workstation.cli.boundary`
    words it), 2 usage error, 128 + n on signal n (130 Ctrl-C, 143 SIGTERM, 129 SIGHUP)."""
    from workstation.cli.boundary import report
    from workstation.core.errors import is_library_panic

    if argv is None:  # the console script (a test calling main(argv) keeps its own handlers)
        _install_signal_handlers()
    argv = list(sys.argv[1:] if argv is None else argv)
    verbose = any(a in ("-v", "--verbose") or (a.startswith("-v") and set(a[1:]) == {"v"}) for a in argv)
    try:
        rc = cli.main(args=argv, prog_name="ws", standalone_mode=False)
    except click.exceptions.Exit as e:
        return e.exit_code
    except click.exceptions.Abort as e:  # click turns KeyboardInterrupt into Abort
        if isinstance(e.__context__, Terminated):
            click.echo(f"Terminated by signal {e.__context__.signum}.", err=True)
            return 128 + e.__context__.signum
        click.echo("Interrupted." if isinstance(e.__context__, KeyboardInterrupt) else "Aborted.", err=True)
        return 130 if isinstance(e.__context__, KeyboardInterrupt) else 1
    except click.ClickException as e:
        e.show()
        return e.exit_code
    except Terminated as e:  # raised outside click's own handler
        click.echo(f"Terminated by signal {e.signum}.", err=True)
        return 128 + e.signum
    except KeyboardInterrupt:
        click.echo("Interrupted.", err=True)
        return 130
    except Exception as e:  # noqa: BLE001 - the boundary: every failure becomes a message
        return report(e, verbose, argv)
    except BaseException as e:  # a library's Rust panic is a BaseException; SystemExit is not ours
        if not is_library_panic(e):
            raise
        return report(e, verbose, argv)
    return rc if isinstance(rc, int) else 0  # a command's click.exceptions.Exit(n) comes back as n


def run() -> None:  # pragma: no cover - console script shim
    sys.exit(main())


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
