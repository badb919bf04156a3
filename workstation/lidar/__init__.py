"""LiDAR simulation: synthetic scenes, platforms, scan patterns, the georeferencing chain,
the simulator and flight planning.

Modules: :mod:`.scene` (labelled scene meshes from TOML recipes), :mod:`.materials`,
:mod:`.shapes`, :mod:`.georef` (laser -> scanner -> body -> level -> map transforms),
:mod:`.platforms` (trajectories), :mod:`.scanners` (scan mechanisms), :mod:`.simulate`
(ray casting, returns, intensity, errors), :mod:`.survey` (presets), :mod:`.planning`.
Nothing heavy is imported here: Open3D loads only when a simulation runs.
"""
