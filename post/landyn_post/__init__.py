"""landyn_post: post-processing of LANDYN result files (HDF5, schema in docs/output.md).

Tools (console scripts, or ``python3 post/landyn_<tool>.py`` without installation):
landyn-plot, landyn-animate, landyn-compare, landyn-export.

Library use::

    from landyn_post import load
    res = load("landyn.h5")
    print(res.crush_length * 1000)   # mm, (n_gears, 3): primary, secondary left, secondary right
"""
from .schema import (DATASETS, SCHEMA_VERSION, STRUTS, LandynFileError, LandynPostError, Result, load)

__version__ = "0.1.0"

__all__ = ["load", "Result", "LandynPostError", "LandynFileError", "DATASETS", "SCHEMA_VERSION", "STRUTS",
           "__version__"]
