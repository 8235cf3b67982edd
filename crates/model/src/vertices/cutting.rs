//! The cut on the vertex ground: each increment searches the least-force
//! mechanism anywhere on the ground (`search`), takes its force at the
//! time scheme's state (`midpoint`), moves the soil by it (`motion`) and
//! lets the slopes avalanche (`avalanche`), as the node
//! grid's increment does (docs/model.md §1).
//!
//! Every case soilcut takes: a blade vertical or raked (the ground held in
//! the sheared coordinates of `Rake`), in plane strain or of finite width
//! (the crescents in the search, the side heaps a field at fixed x that
//! the vertices spill into, `spill`), at constant depth or on a depth path,
//! in a bin or not, under every band rule, the sampled search or the
//! exhaustive one (docs/model.md §1.2, §2.8).

use super::avalanche::Settled;
use super::midpoint::{half_slip, midpoint_force};
use super::motion::Cut;
use super::scan::{Pick, Scan};
use super::search::{PickObserver, VertexSearch};
use super::strength::Columns;
use super::{Quiet, Vertices};
use crate::band::{stretch, BandMotion};
use crate::case::{BandStrengthRule, Case, TimeScheme, VertexGround};
use crate::crescent::Crescents;
use crate::discretisation::{Context, Discretisation};
use crate::landscape::Candidate;
use crate::mechanism::Loads;
use crate::rake::Rake;
use crate::side_heaps::{Edges, SideHeaps};
use crate::step::{force_factor, ProfilePoint, StepError, StepRecord};
use crate::tool::tool_state;

/// Flat fresh ground appended when the search reaches the end, in d.
const GROW_DEPTHS: f64 = 4.0;
/// Spacing of a slip line's samples, in d (it has no band width).
const SLIP_LINE_SAMPLES: f64 = 1.0 / 64.0;
/// No band emerges farther ahead of the face than this, in d.
const MAX_REACH_DEPTHS: f64 = 1000.0;

/// A cut simulated on the vertex ground.
#[derive(Clone, Debug)]
pub struct Cutting {
    /// The case's `run.ground` keys.
    keys: VertexGround,
    rake: Rake,
    ground: Vertices,
    search: VertexSearch,
    /// The ground as the last avalanche left it (`Settled`, a cache).
    settled: Settled,
    /// Soil spilled around the edges of a blade of finite width, a field
    /// at fixed x every `run.vertex_spacing` (the vertices move).
    side: SideHeaps,
    /// w for a blade of finite width, else 1: forces and masses per blade.
    per_blade: f64,
}

impl Cutting {
    /// The cut of a validated `case` on flat ground of fresh soil from the
    /// face to the travel plus 8 d ahead (or the end wall, `bin.length`,
    /// if nearer), in pieces `run.vertex_spacing`
    /// long (where the soil that avalanches ahead of a band lands; a heap
    /// on one long piece would spread thin over all of it). The search
    /// grows it as it needs, up to the wall.
    pub fn new(case: &Case, keys: VertexGround) -> Self {
        let d = case.blade.depth;
        let ahead = case.run.travel + 8.0 * d;
        let length = case.bin.length.map_or(ahead, |wall| wall.min(ahead));
        let ground = Vertices::flat(length, keys.spacing, case.deepest(), case.soil.unit_weight);
        Self::resumed(case, keys, (ground, SideHeaps::default()), 0)
    }

    /// The cut of `case` resumed on `ground` beside `side` after
    /// `evaluations` Eq. (1) evaluations (a restored snapshot; the search
    /// keeps no state from one increment to the next).
    pub(crate) fn resumed(
        case: &Case,
        keys: VertexGround,
        (ground, side): (Vertices, SideHeaps),
        evaluations: u64,
    ) -> Self {
        let mut search = VertexSearch::default();
        search.evaluations = evaluations;
        Cutting {
            keys,
            rake: Rake::new(case.blade.rake),
            ground,
            search,
            settled: Settled::default(),
            side,
            per_blade: case.blade.width.unwrap_or(1.0),
        }
    }

    /// The ground now.
    pub fn ground(&self) -> &Vertices {
        &self.ground
    }

    /// The side heaps now (empty in plane strain).
    pub fn side_heaps(&self) -> &SideHeaps {
        &self.side
    }

    /// The least-force mechanism of the next increment (§2 on the ground)
    /// under `scan` (`Cutting::scan`), every first-stage candidate handed
    /// to `observer` if there is one.
    fn search_next(
        (search, ground): (&mut VertexSearch, &mut Vertices),
        (at, scan): (&Context, &Scan),
        observer: Option<PickObserver>,
    ) -> Result<Pick, StepError> {
        let u = ground.x[0];
        search
            .run(ground, scan, observer)
            .ok_or_else(|| StepError::no_mechanism(at.done + 1, u, at.case.bin.length))
    }

    /// The tip's depth now and its rise per unit of travel over the next
    /// increment (a depth path, §8.3; 0 at constant depth).
    fn tip(&self, case: &Case) -> (f64, f64) {
        let (u, v0) = (self.ground.x[0], case.run.increment);
        let depth = case.tip_depth(u);
        (depth, (depth - case.tip_depth(u + v0)) / v0)
    }

    /// What the search needs besides the ground, this increment, beside
    /// `side`, the cut's side heaps (borrowed apart from the cut, which
    /// the search then advances).
    fn scan<'a>(&self, at: &Context<'a>, side: &'a SideHeaps) -> Scan<'a> {
        let (c, d) = (at.case, at.case.blade.depth);
        let u = self.ground.x[0];
        let band_width = c.soil.band_width;
        let (tip, climb) = self.tip(c);
        let far = u + MAX_REACH_DEPTHS * d;
        Scan {
            laws: at.laws,
            loads: Loads::at_face(c, &self.rake, self.ground.y[0] + tip),
            face: at.laws.face.for_climb(climb),
            depth: tip,
            band_width,
            sample: sample_spacing(c, self.keys.samples_per_band),
            thins_samples: band_width > 0.0 && self.keys.samples_per_band > 0.0,
            vertex_spacing: self.keys.spacing,
            resolution: c.run.increment,
            advance: c.run.increment,
            snap: 0.5 * self.keys.spacing,
            grow: GROW_DEPTHS * d,
            // The ground never grows past the end wall, nor past
            // MAX_REACH_DEPTHS ahead of the face: the search's loop over
            // the pieces ends (a bin of 1e20 before a blade of 1 grew
            // pieces of 4 d without end where no band was admissible).
            reach: c.bin.length.map_or(far, |wall| wall.min(far)),
            rake: self.rake,
            crescents: {
                let spacing = self.keys.spacing;
                let face_node = (u / spacing).floor() as usize;
                Crescents::of(c, side, (u, face_node, spacing))
            },
            choose_at_midpoint: self.keys.time_scheme == TimeScheme::MidpointForce
                && !c.soil.softens(),
            // The floor's cap: θr, or 0° where the columns are unfloored.
            columns: match c.choices.band_strength {
                BandStrengthRule::Footprint => None,
                BandStrengthRule::CrossedColumns => Some(Columns::new(c.soil.repose, self.rake)),
                BandStrengthRule::CrossedColumnsUnfloored => Some(Columns::new(0.0, self.rake)),
            },
        }
    }

    /// The motion of the band `pick` (M18, M35): rise v0 tan(β + ψ), slip
    /// Δut = v0 cos ψ / cos(β + ψ); a slip line's v0 tan β and v0 / cos β.
    fn cut(&self, case: &Case, pick: &Pick) -> Cut {
        let (c, t) = (case, pick.tan_beta);
        let v0 = c.run.increment;
        let (tip, climb) = self.tip(c);
        let line = Cut {
            depth: tip,
            deepening: -climb * v0,
            emergence: pick.x,
            // M16, on a raked blade's coordinates stretched by tan β' / tan β.
            thickness: c.soil.band_width * (1.0 + t * t).sqrt() * stretch(pick.grid_slope, t),
            width: c.soil.band_width,
            min_spacing: 0.25 * v0,
            snap: 0.5 * self.keys.spacing,
            advance: v0,
            rise: 0.0,
            slip: 0.0,
            tan_psi: 0.0,
            rake: self.rake,
            band_shear: c.choices.band_shear,
            unit_weight: c.choices.unit_weight,
        };
        let band = (pick.grid_slope, t, pick.angles.dilation);
        let (motion, banded) = BandMotion::of(line.thickness > 0.0, band, &self.rake, v0);
        Cut {
            thickness: if banded { line.thickness } else { 0.0 },
            rise: motion.rise,
            slip: motion.slip,
            tan_psi: motion.tan_psi,
            ..line
        }
    }

    /// After the motion (M49, M50): the slopes avalanche, the quiet
    /// vertices merge (with `run.merge_tolerance` above 0) and a blade of
    /// finite width spills around its edges.
    fn settle(&mut self, c: &Case) {
        let d = c.blade.depth;
        let slopes = self.rake.repose_slopes(c.soil.repose.to_radians().tan());
        self.ground
            .relax_after(slopes, self.keys.spacing, &mut self.settled);
        if self.keys.merge_tolerance > 0.0 {
            let quiet = Quiet {
                tolerance: self.keys.merge_tolerance,
                // ur; d where the law softens at once (ur = 0).
                shear_scale: if c.soil.residual_shear > 0.0 {
                    c.soil.residual_shear
                } else {
                    d
                },
                unit_weight: c.soil.unit_weight,
                depth: d,
                longest: self.keys.spacing,
            };
            self.ground.merge_quiet(1, self.ground.pieces(), &quiet);
        }
        if let Some(width) = c.blade.width {
            let edges = Edges {
                width,
                tan_repose: c.soil.repose.to_radians().tan(),
            };
            self.ground.spill(&mut self.side, edges, self.keys.spacing);
        }
    }
}

impl Discretisation for Cutting {
    fn blade_position(&self) -> f64 {
        self.ground.x[0]
    }

    fn mass(&self) -> f64 {
        self.ground.mass() * self.per_blade
    }

    fn mass_spilled(&self) -> f64 {
        self.side.spilled * self.per_blade
    }

    fn evaluations(&self) -> u64 {
        self.search.evaluations
    }

    fn floor(&self) -> f64 {
        self.ground.floor
    }

    /// The surface at the vertices from the face on, each with the state
    /// of the piece that starts there (the last, of the piece it ends), at
    /// its physical x (`Rake`).
    fn profile(&self, at: &Context) -> Vec<ProfilePoint> {
        let g = &self.ground;
        let (tip, _) = self.tip(at.case);
        (0..g.x.len())
            .map(|k| {
                let piece = k.min(g.pieces() - 1);
                ProfilePoint {
                    x: self.rake.x(g.x[k], g.y[k], tip),
                    y: g.y[k],
                    accumulated_shear: g.accumulated_shear[piece],
                    unit_weight: g.unit_weight[piece],
                    ridge_height: self.side.height_at(g.x[k], self.keys.spacing),
                }
            })
            .collect()
    }

    /// Every candidate the next increment's first stage evaluates, without
    /// pruning: its samples every dB / K along the ground, up to where the
    /// stopping rule ends the scan (the least force found then), and the
    /// one the increment takes, which the second stage may have found
    /// between them (so that the least is the force the step records
    /// under the explicit rule; the midpoint force records that band's
    /// force half an increment on).
    fn landscape(&mut self, at: &Context) -> Result<Vec<Candidate>, StepError> {
        let mut picks = Vec::new();
        let scan = self.scan(at, &self.side);
        let parts = (&mut self.search, &mut self.ground);
        let chosen = Self::search_next(parts, (at, &scan), Some(&mut |p: &Pick| picks.push(*p)))?;
        if !picks.contains(&chosen) {
            // In order along the ground, as the samples are.
            let at = picks.partition_point(|p| p.x < chosen.x);
            picks.insert(at, chosen);
        }
        let scale = at.case.force_scale();
        let (tip, _) = self.tip(at.case);
        Ok(picks
            .iter()
            .map(|p| Candidate {
                x_emergence: self.rake.x(p.x, p.y, tip),
                y_emergence: p.y,
                beta_deg: p.tan_beta.atan().to_degrees(),
                force: p.force * self.per_blade,
                force_norm: p.force / scale,
                friction_deg: p.angles.friction.to_degrees(),
                dilation_deg: p.angles.dilation.to_degrees(),
            })
            .collect())
    }

    /// The increment (M48, M49, M50), its force components by (M12).
    fn step(&mut self, at: &Context) -> Result<StepRecord, StepError> {
        let c = at.case;
        let scan = self.scan(at, &self.side);
        let pick = Self::search_next((&mut self.search, &mut self.ground), (at, &scan), None)?;
        let keys = self.keys;
        let pick = match keys.time_scheme {
            TimeScheme::Explicit => pick,
            // The search compared the midpoint forces already.
            TimeScheme::MidpointForce if scan.choose_at_midpoint => pick,
            TimeScheme::MidpointForce => {
                midpoint_force(&self.ground, &scan, pick, half_slip(&scan, &pick))
            }
        };
        let (d, u) = (c.blade.depth, self.ground.x[0]);
        // The tip's depth and the face friction of the search's scan.
        let (tip, face) = (scan.depth, scan.face);
        let face_top = self.ground.y[0];
        let cut = self.cut(c, &pick);
        let moved = match self.ground.apply(&cut) {
            Some(moved) => moved,
            None => self
                .ground
                .apply(&slip_line(
                    &cut,
                    (pick.grid_slope, pick.tan_beta),
                    &self.rake,
                ))
                .expect("a slip line always moves"),
        };
        // The face at exactly n v0 after n increments, as on the node grid,
        // not a sum of n increments' rounding.
        self.ground.x[0] = (at.done + 1) as f64 * c.run.increment;
        self.settle(c);
        let mobilisation = face.mobilisation(pick.tan_beta, pick.angles.dilation);
        let omega = at.laws.face.angle(mobilisation);
        let force = pick.force * self.per_blade;
        let (force_h, force_v) = (force * omega.cos(), force * omega.sin());
        let tool = tool_state(&c.blade, u, tip, face_top, [force_h, force_v]);
        Ok(StepRecord {
            step: at.done + 1,
            u,
            u_over_d: u / d,
            force,
            force_norm: pick.force / c.force_scale(),
            force_h,
            force_v,
            beta_deg: pick.tan_beta.atan().to_degrees(),
            x_emergence: self.rake.x(pick.x, pick.y, tip),
            mass: self.mass(),
            y_emergence: pick.y,
            friction_deg: pick.angles.friction.to_degrees(),
            slip: cut.slip,
            dilation_deg: pick.angles.dilation.to_degrees(),
            dilation_area: moved.dilation_area,
            depth: tip,
            mass_spilled: self.mass_spilled(),
            weight: pick.weight * self.per_blade,
            force_factor: force_factor(pick.force, pick.weight),
            face_friction_deg: mobilisation * c.blade.wall_friction,
            moment: tool.moment,
            tool_x: tool.x,
            tool_y: tool.y,
            tool_rotation: tool.rotation,
        })
    }
}

/// Spacing of the search's first-stage samples along the ground: dB / K
/// (`run.samples_per_band` = K, (M47)), d/64 for a slip line (it has no
/// band width); with K = 0 the exhaustive search, every v0 (the
/// increment, as the reference grid's nodes are), its local minima within
/// the slack narrowed to v0 as every search's are: the least force of
/// every emergence point v0 apart and every vertex, and nothing the
/// bounds do not prove to lose.
fn sample_spacing(case: &Case, samples: f64) -> f64 {
    let band_width = case.soil.band_width;
    if samples == 0.0 {
        case.run.increment
    } else if band_width > 0.0 {
        band_width / samples
    } else {
        SLIP_LINE_SAMPLES * case.blade.depth
    }
}

/// The slip line of `band`'s lower boundary (M14, M15), of slope
/// `grid_slope` in the ground's coordinates and tan β physically.
fn slip_line(band: &Cut, (grid_slope, tan_beta): (f64, f64), rake: &Rake) -> Cut {
    let motion = BandMotion::slip_line((grid_slope, tan_beta), rake, band.advance);
    Cut {
        thickness: 0.0,
        rise: motion.rise,
        slip: motion.slip,
        tan_psi: motion.tan_psi,
        ..*band
    }
}
