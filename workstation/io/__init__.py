"""Files <-> core types. ``read_cloud`` / ``write_cloud`` dispatch on the extension."""

from .atomic import atomic_dir, atomic_path, atomic_paths, check_output, check_outputs, work_folder
from .registry import FORMATS, format_of, iter_chunks, read_cloud, write_cloud

__all__ = ["atomic_dir", "atomic_path", "atomic_paths", "check_output", "check_outputs", "work_folder", "FORMATS", "format_of", "iter_chunks", "read_cloud", "write_cloud"]
