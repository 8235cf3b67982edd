//! `soilcut run CASE --ensemble N`: the case's N perturbed members in
//! parallel and the spread of their window means (`soilcut-study`'s
//! `ensemble`).

use super::{CaseOutput, Failure};
use crate::study_cmd::{progress, study_failure};
use soilcut_study::ensemble::Ensemble;
use soilcut_study::BaseCase;

/// Runs the ensemble of `target`'s case and writes its folder.
pub fn run_ensemble(
    target: &CaseOutput,
    members: usize,
    jobs: usize,
    plots: bool,
    quiet: bool,
) -> Result<(), Failure> {
    let path = target.case.as_path();
    let overrides = target.overrides()?;
    let base = BaseCase::read(path, overrides)
        .map_err(|e| Failure::argument(path, "--set", &target.set, e))?;
    let case = base.load(&[]).map_err(|e| Failure::input(path, e))?.case;
    let out = target.out_or(&case.name);
    let claim = target.claim(&out)?;
    super::warn_accuracy(&case);
    let ensemble = Ensemble {
        base,
        members,
        jobs,
    };
    let result = ensemble
        .run(&progress(quiet, "members"))
        .map_err(|e| study_failure(path, e))?;
    result.write_into(claim, plots).map_err(Failure::output)?;
    if !quiet {
        let w = &result.whole_run;
        println!(
            "{}: ensemble of {} ({}), mean force_norm {:.4} (sd {:.4}, {:.4} to {:.4}), outputs in {}",
            case.name,
            result.members.len(),
            result.perturbation.rule(),
            w.mean,
            w.std,
            w.min,
            w.max,
            out.display()
        );
    }
    Ok(())
}
