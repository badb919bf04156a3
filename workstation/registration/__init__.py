"""Scan registration, merging and colouring.

- :mod:`.register` — ``register(source, target, RegisterParams)``: the pairwise stage
  (coarse from FPFH features, then ICP), returning a checked ``RegistrationResult``.
- :mod:`.preprocess` — spacing / voxel estimation, downsampling, normals, outliers, FPFH.
- :mod:`.coarse` — FPFH + RANSAC, Fast Global Registration, max-clique estimator.
- :mod:`.icp` — point-to-point (optionally 7-DoF), point-to-plane, coloured, generalised ICP.
- :mod:`.voxelmap` — point-to-plane ICP with voxel-hash correspondences for millions of points.
- :mod:`.transforms` — Horn/Umeyama fits from point pairs with residuals, transform helpers.
- :mod:`.posegraph` — multi-scan pose graph with loop closures and an edge residual table.
- :mod:`.merge` — merging clouds with poses, attribute union, overlap thinning.
- :mod:`.colorize` — colouring from oriented photos with depth-tested visibility.

Nothing heavy is imported here; Open3D is imported inside the functions that use it.
"""
