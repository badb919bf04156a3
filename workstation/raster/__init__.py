"""Raster products: DSM/DTM/CHM gridding (:mod:`.dem`, TIN machinery in :mod:`.grid`), slope,
aspect and hillshade (:mod:`.terrain`), contour lines (:mod:`.contours`), true orthophotos
(:mod:`.ortho`) and the synthetic aerial rig used to test them (:mod:`.synthetic_aerial`).

Modules import their heavy libraries (scipy, contourpy, rasterio, cv2, open3d) inside the
functions that need them.
"""
