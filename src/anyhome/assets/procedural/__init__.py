"""Procedural asset factories, one module per group of related families.

Each module registers its families with :mod:`anyhome.assets.registry` on import;
the registry imports the modules named in ``MODULES`` the first time it is asked.
"""

MODULES = ("appliances", "beds", "booths", "care_shop", "clinic", "court", "crafts", "curios", "dairy", "decor",
           "depot", "exhibits",
           "fixtures", "flames", "games", "industry", "instruments", "kitchen_bath", "lab_kit", "machines", "misc",
           "outdoor", "performance", "pets", "photo", "play", "seating", "specialist", "stable", "storage", "tables",
           "training", "utility", "vehicles", "worship", "yard")
