"""soilcut: soil cutting by sequential limit analysis (Jin & Hambleton,
"Simulation of the Cutting Process in Softening and Hardening Soils"). In
short::

    import soilcut
    case = soilcut.Case.from_file("cases/paper/original.toml")
    result = soilcut.run(case.set("run.increment", 0.08))
    result.history["force_norm"]          # NumPy array, P/(γ0 d²)
    result.save("out/original")           # the folder `soilcut run` writes

    spread = soilcut.run(case, ensemble=7)  # 7 perturbed members: the spread
    spread.windows["std"]                 # of every unit-window mean force

    study = soilcut.sensitivity(case, {"soil.peak_shear": (1, 3)}, method="morris")
    study.indices                         # indices.csv as a DataFrame

    sim = soilcut.Simulation(case)        # step by step, for a control loop
    for step in sim:
        step.force, step.beta_deg
    branch = copy.deepcopy(sim)           # or Simulation.from_snapshot(sim.snapshot())
    branch.advance_to(80.0, depth=15.0)   # to u = 80, the tip linearly to 15

    import soilcut.gym                    # gymnasium's soilcut/Cutting-v0 (optional)

Lengths are in the case's unit (the paper's cases use mm), angles in
degrees, forces per unit width.
"""

from ._case import Case
from ._errors import AccuracyWarning, CaseError, CaseFormWarning, SnapshotError, StepError
from ._run import Ensemble, Frame, RunResult, run
from ._sensitivity import SensitivityResult, sensitivity
from ._soilcut import Simulation, Step, __version__
from ._study import (
    Bounds,
    FitResult,
    Landscape,
    LandscapeMap,
    analytic,
    bounds,
    fit,
    landscape,
    landscape_map,
    sweep,
)

__all__ = [
    "AccuracyWarning",
    "CaseFormWarning",
    "Bounds",
    "Case",
    "CaseError",
    "Ensemble",
    "FitResult",
    "Landscape",
    "Frame",
    "RunResult",
    "SensitivityResult",
    "Simulation",
    "SnapshotError",
    "Step",
    "StepError",
    "__version__",
    "analytic",
    "bounds",
    "fit",
    "landscape",
    "LandscapeMap",
    "landscape_map",
    "run",
    "sensitivity",
    "sweep",
]
