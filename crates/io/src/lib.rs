//! soilcut-io: case files in, output files out. No terminal code: the
//! command line (`soilcut`) formats the errors of this crate.
//!
//! * [`read_case`]: a TOML case file plus `--set` [`Override`]s → a resolved,
//!   validated [`LoadedCase`] (and its `case.resolved.toml`);
//!   [`parse_case_table`] and [`load_case_table`] do it in two steps for a
//!   front end that keeps the table and changes keys.
//! * [`Columns`]: the numbers of a CSV file before they are text, which
//!   front ends hand out as arrays ([`RunTables`] for a run).
//! * [`RunOutput`]: `history.csv`, `profile.csv`, `summary.json`,
//!   `case.resolved.toml`; [`write_output_dir`] places them atomically, and
//!   [`OutputDir`] claims a folder when a command starts (`place`).
//! * [`landscape_csv`]: every candidate mechanism of one increment;
//!   [`landscape_map_csv`]: landscapes through a run, binned by distance.
//! * [`read_measured_curve`]: a measured force-displacement curve (`u,force`,
//!   optionally `weight`), read with the `csv` crate.
//! * [`frames_csv`]: the surfaces captured during a run; [`read_finished_run`]
//!   reads a finished run's files back for drawing; [`run_case`] runs a
//!   case capturing the frames, [`record_case`] gives its files.
//! * `write_run_dir`: a run's folder with its pictures (`draw_run_dir`),
//!   the same from every front end (feature `pictures`).

#![warn(missing_docs)]

mod baselines;
mod bounds;
mod case_file;
mod columns;
mod csv_text;
mod error;
mod finished;
mod history;
mod landscape;
mod measured;
mod output;
mod overrides;
mod panic;
#[cfg(feature = "pictures")]
mod pictures;
mod place;
mod record;

pub use baselines::{baselines, BaselineFactors, Baselines, NarrowBaseline, NormalisedBaseline};
pub use bounds::{
    bounds_columns, bounds_json, bounds_options, field_name, floor_name, strength_name,
    BOUNDS_HEADER,
};
pub use case_file::{
    case_from_note, load_case_table, parse_case, parse_case_bytes, parse_case_table, read_case,
    unknown_key, LoadedCase,
};
pub use columns::Columns;
pub use csv_text::CsvText;
pub use error::{visible, InputError, OutputError, RunFilesError};
pub use finished::{
    frames_columns, frames_csv, read_finished_run, FinishedRun, SurfaceFrame, FRAMES_HEADER,
    FRAME_ROWS,
};
pub use history::{history_columns, history_value, HistoryColumn, HISTORY, HISTORY_HEADER};
pub use landscape::{
    check_landscape_at, check_landscape_every, far_ties, landscape_at, landscape_columns,
    landscape_csv, landscape_map, landscape_map_columns, landscape_map_csv, MapColumn,
    LANDSCAPE_HEADER, LANDSCAPE_MAP_HEADER, MAP_BIN,
};
pub use measured::{
    parse_measured, parse_measured_bytes, parse_measured_curve, read_measured, read_measured_curve,
    MeasuredCurve,
};
pub use output::{peak_prominence_rule, profile_columns, RunOutput, RunTables, PROFILE_HEADER};
pub use overrides::{parse_value, Override};
pub use panic::panic_message;
#[cfg(feature = "pictures")]
pub use pictures::{compare, draw_run_dir, run_data, write_run_dir, write_run_into, PictureError};
pub use place::{
    abandon_outputs, check_output_dir, on_abandon, write_output_dir, write_output_dir_then,
    OutputDir, Published, Registered, MAX_NAME_BYTES, OUTPUT_MARKER,
};
pub use record::{record_case, record_files, run_case, CaseRun, RecordedRun, ANIMATION_FRAMES};
