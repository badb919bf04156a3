"""Files <-> core types. ``read_cloud`` / ``write_cloud`` dispatch on the extension."""

from .atomic import atomic_dir, atomic_path, check_output
from .registry import FORMATS, format_of, iter_chunks, read_cloud, write_cloud

__all__ = ["atomic_dir", "atomic_path", "check_output", "FORMATS", "format_of", "iter_chunks", "read_cloud", "write_cloud"]
