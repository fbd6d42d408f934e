"""Procedural asset factories, one module per group of related families.

Each module registers its families with :mod:`anyhome.assets.registry` on import;
the registry imports the modules named in ``MODULES`` the first time it is asked.
"""

MODULES = ("beds", "care_shop", "curios", "decor", "fixtures", "games", "kitchen_bath", "misc", "outdoor",
           "performance", "pets", "seating", "storage", "tables", "vehicles", "worship")
