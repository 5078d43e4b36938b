"""The catalogue of parts as pure geometry: (r, z) outlines with named segments and their parameters
(``catalog.py``, ``profiles.py``).  No gmsh here: ``shockfem.geometry`` draws and meshes them, and
the scene checker reads the catalogue's parameter lists below both."""
