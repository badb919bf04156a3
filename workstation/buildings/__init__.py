"""Buildings from classified point clouds: roof planes, footprints, LoD1.2/LoD2.2 models,
CityJSON and glTF exports, and rooftop solar potential.

Public entry points: :func:`workstation.buildings.planes.segment_planes`,
:func:`workstation.buildings.footprints.extract_footprints`,
:func:`workstation.buildings.models.build_models`, :func:`workstation.buildings.solar.annual_irradiation`
and the whole chain :func:`workstation.buildings.pipeline.reconstruct_buildings`.
"""
