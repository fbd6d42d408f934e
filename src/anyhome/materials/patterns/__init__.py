"""Pattern generators, one module per family of surfaces.

Each generator is ``gen(rng, n, tint, roughness, variant) -> (color, height,
roughness)`` (see :data:`anyhome.materials.noise.Pattern`): ``tint`` is a (3,) sRGB
colour in [0, 1], the arrays are (n, n[, 3]) and tile over the unit square. The height
field must not depend on ``tint`` (normal maps are shared between colours).
"""
