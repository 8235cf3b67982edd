//! The sampled search (`run.samples_per_band` > 0, docs/model.md §2.8)
//! against the exhaustive one: at every checked increment its force is
//! never below the least of the full landscape (it evaluates candidates
//! exactly, only fewer of them), equals it at almost every increment, and
//! exceeds it rarely and by little where a V-shaped minimum lies between
//! samples that are not local minima. Checked on the paper's softening
//! cases and on random cases.

use crate::common;

#[test]
fn the_sampled_search_finds_the_least_force_on_the_softening_paper_cases() {
    for which in ["fig5", "table1-hs", "table1-s"] {
        let mut case = common::refined(which, 2.5, 250.0);
        case.run.samples_per_band = 8.0;
        assert!(
            case.search_stride() >= 4,
            "{which}: a stride of several nodes"
        );
        let (checked, above, largest) = common::least_force_excess(&case, 5);
        // Measured (d/250, 2.5 d, every fifth increment): at most 2 of 125
        // above, by at most 1.3e-5, before M26's dilation gap (issue 38),
        // 6 of 125 on Table 1 HS with it; searching around the least
        // sample alone gave 5 of 125 on Fig. 5, by up to 2.9e-3.
        assert!(
            above * 20 <= checked,
            "{which}: {above} of {checked} above the least"
        );
        assert!(largest < 1e-3, "{which}: {largest:e} above the least");
    }
}
