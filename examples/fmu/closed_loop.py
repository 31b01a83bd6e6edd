#!/usr/bin/env python3
"""A loop closed in Python around the LANDYN FMU (docs/api.md, "FMU"), with FMPy's FMU2Slave.

    python3 examples/fmu/closed_loop.py [build/release/landyn.fmu]

The lander of the default deck starts 1 m above the ground (initial_state.clearance = 1.0) at the
default 4 m/s descent rate. A controller holds the descent engine's thrust at the lander's weight,
upward: the lander frame's z axis points down, so the force input is engine.force.z = -m g. Each
1 ms communication step it reads the footpad contact outputs; at the first contact it cuts the
thrust. It prints the cut-off time, the descent rate then, and the final strokes.
"""
import os
import shutil
import sys

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave, fmi2Discard, fmi2LastSuccessfulTime, fmi2Terminated

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    fmu = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "..", "build", "release", "landyn.fmu")
    md = read_model_description(fmu)
    var = {v.name: v for v in md.modelVariables}
    vr = {name: v.valueReference for name, v in var.items()}
    n_gears = int(var["gears.n_gears"].start)
    weight = float(var["lander.mass"].start) * float(var["simulation.gravity"].start)   # N

    unzipped = extract(fmu)
    slave = FMU2Slave(guid=md.guid, unzipDirectory=unzipped, modelIdentifier=md.coSimulation.modelIdentifier,
                      instanceName="closed_loop")
    stop_time, h = 1.0, 1.0e-3                                     # s
    slave.instantiate()
    slave.setupExperiment(startTime=0.0, stopTime=stop_time)
    slave.enterInitializationMode()
    slave.setReal([vr["initial_state.clearance"]], [1.0])          # start 1 m above the ground
    slave.exitInitializationMode()

    contacts = [vr["gear%d.footpad.contact" % g] for g in range(1, n_gears + 1)]
    strokes = [vr["gear%d.strut%d.stroke" % (g, s)] for g in range(1, n_gears + 1) for s in (1, 2, 3)]
    thrust_on, t_cut, v_cut, n = True, None, None, 0
    t = 0.0
    while t < stop_time - 1e-12:
        slave.setReal([vr["engine.force.z"]], [-weight if thrust_on else 0.0])   # lander -z is up
        try:
            slave.doStep(currentCommunicationPoint=t, communicationStepSize=min(h, stop_time - t))
        except FMICallException as exc:
            if exc.status == fmi2Discard and slave.getBooleanStatus(fmi2Terminated):
                print("the run ended (at rest or tipped over) at t = %.4f s" % slave.getRealStatus(fmi2LastSuccessfulTime))
                break
            raise
        n += 1
        t = n * h
        if thrust_on and max(slave.getReal(contacts)) > 0.5:
            thrust_on, t_cut = False, t
            v_cut = slave.getReal([vr["velocity.z"]])[0]

    final = slave.getReal(strokes)
    slave.terminate()
    slave.freeInstance()
    shutil.rmtree(unzipped, ignore_errors=True)

    if t_cut is None:
        print("no footpad touched the ground before t = %.3f s" % stop_time)
        return 1
    print("thrust %.0f N (the lander's weight) held until the first footpad contact" % weight)
    print("thrust cut at t = %.3f s, descent rate %.3f m/s" % (t_cut, v_cut))
    print("final strokes at t = %.3f s [mm] (primary, secondary left, secondary right):" % t)
    for g in range(n_gears):
        print("  gear %d: %7.1f %7.1f %7.1f" % ((g + 1,) + tuple(1e3 * s for s in final[3 * g:3 * g + 3])))
    return 0


if __name__ == "__main__":
    sys.exit(main())
