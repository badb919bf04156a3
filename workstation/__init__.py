"""workstation: a point cloud and mesh workstation."""

__version__ = "0.1.0"
