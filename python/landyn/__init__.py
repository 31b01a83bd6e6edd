"""landyn: the LANDYN touchdown simulation from Python, over its C API (liblandyn.so, include/landyn.h).

    import landyn
    with landyn.Simulation("input/lc3.nml", overrides={"initial_state%velocity(3)": 3.5}) as sim:
        sim.advance_to(0.05)                              # [s]
        sim.set_input(force=(0.0, 0.0, -2.0e4))           # engine force from now on, lander frame [N]
        sim.advance_to(0.5)
        print(sim.outcome, sim["gear1.strut1.stroke"], sim.units["gear1.strut1.stroke"])

Reference: docs/api.md (Python API). The library is found through LANDYN_LIBRARY, else the build
tree of the checkout the package was installed from (build/release/liblandyn.so); see library_path().
"""
from ._lib import library_path
from .errors import (LandynClosedError, LandynError, LandynFailedError, LandynFileError, LandynInputError,
                     LandynLibraryError, LandynOrderError, LandynOutputNameError)
from .simulation import OUTCOMES, Simulation, overrides_text, version

__version__ = "0.1.0"

__all__ = ["Simulation", "OUTCOMES", "overrides_text", "version", "library_path", "LandynError",
           "LandynLibraryError", "LandynInputError", "LandynOutputNameError", "LandynOrderError",
           "LandynFailedError", "LandynFileError", "LandynClosedError"]
