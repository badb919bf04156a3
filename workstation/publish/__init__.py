"""Shareable products: COPC point clouds (:mod:`workstation.publish.copc`), 3D Tiles and the
static web viewer that a client opens in a browser."""
