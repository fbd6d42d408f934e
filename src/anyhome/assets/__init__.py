"""Assets: procedural mesh factories per object family and the records that rebuild them.

``assign_asset(obj, rng, style)`` picks a family for an object and samples its
parameters; the returned record goes into ``HouseObject.asset`` and
``build_object_mesh(obj)`` rebuilds the mesh (local frame: centred on x/y, bottom at
z = 0, front facing +y, fitted exactly to ``obj.size``) from it alone.
"""

from anyhome.assets.registry import assign_asset, build_object_mesh, families, family_for

FAMILIES: list[str] = families()
"""Names of every procedural family, sorted."""

__all__ = ["FAMILIES", "assign_asset", "build_object_mesh", "family_for"]
