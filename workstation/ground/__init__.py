"""Ground filtering (SMRF, CSF, PMF, PTD, baselines, auto), noise, height above ground, and the
ISPRS-style evaluation. Each filter is a function ``Cloud -> Cloud`` with a frozen parameter
dataclass; :func:`workstation.ground.methods.ground_filter` runs one by name."""
