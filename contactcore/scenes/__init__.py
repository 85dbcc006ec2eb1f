"""The built-in scenes, one TOML file each (``A.toml``, ...), read by
:func:`contactcore.scene_files.load_scene` by name: a package, holding no
code, so that the files install with the project (pyproject's package-data)."""
