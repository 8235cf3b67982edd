//! Pictures: `soilcut run` draws them for every shipped case, `soilcut plot`
//! redraws the same bytes, `--no-plots` leaves the results unchanged,
//! `soilcut compare` overlays runs, and `soilcut run --ensemble` draws its
//! members and their envelope. A run that several tests read is run once
//! ([`shared_run`]).

use crate::readme::copy_dir;
use std::collections::BTreeMap;
use std::fs;
use std::io::Cursor;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::{Arc, Mutex, OnceLock};

const SHORT: [&str; 4] = ["--set", "run.travel=20", "--set", "run.increment=0.2"];

/// Files every drawn run has, relative to its output folder.
const PICTURES: [&str; 7] = [
    "plots/force.png",
    "plots/beta.png",
    "plots/deformation.png",
    "plots/force.svg",
    "plots/beta.svg",
    "plots/deformation.svg",
    "animation.gif",
];

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Every case file under cases/, sorted.
fn case_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "toml") {
                out.push(path);
            }
        }
    }
    let mut files = Vec::new();
    walk(&workspace().join("cases"), &mut files);
    files.sort();
    files
}

fn soilcut(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_soilcut"))
        .args(args)
        .current_dir(cwd)
        .output()
        .unwrap()
}

fn assert_ok(o: &Output) {
    assert!(
        o.status.success(),
        "{:?}: {}",
        o.status,
        String::from_utf8_lossy(&o.stderr)
    );
}

fn run_short(case: &Path, out: &Path, extra: &[&str]) {
    let mut args = vec![
        "run",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend(SHORT);
    args.extend(extra);
    assert_ok(&soilcut(&args, out.parent().unwrap()));
}

/// The folder of `soilcut run CASE` [`SHORT`] `extra`, run once for all
/// the tests of this file that read it, in `CARGO_TARGET_TMPDIR` (emptied
/// by the first of them): a test that changes a run's folder changes a
/// copy ([`copy_dir`]).
fn shared_run(case: &Path, extra: &[&str]) -> PathBuf {
    static RUNS: Mutex<BTreeMap<String, Arc<OnceLock<PathBuf>>>> = Mutex::new(BTreeMap::new());
    static ROOT: OnceLock<PathBuf> = OnceLock::new();
    let key = format!("{} {}", case.display(), extra.join(" "));
    let cell = Arc::clone(RUNS.lock().unwrap().entry(key.clone()).or_default());
    cell.get_or_init(|| {
        let root = ROOT.get_or_init(|| {
            let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("plots");
            let _ = fs::remove_dir_all(&root);
            fs::create_dir_all(&root).unwrap();
            root
        });
        let name: String = key
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        let out = root.join(name);
        run_short(case, &out, extra);
        out
    })
    .clone()
}

fn assert_png(path: &Path) {
    let bytes = fs::read(path).unwrap();
    let mut reader = png::Decoder::new(Cursor::new(bytes))
        .read_info()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut pixels).unwrap();
    assert!(
        info.width >= 800 && info.height >= 400,
        "{}: {info:?}",
        path.display()
    );
    assert!(
        pixels.iter().any(|&p| p < 100),
        "{}: something is drawn",
        path.display()
    );
}

fn assert_svg(path: &Path) {
    let text = fs::read_to_string(path).unwrap();
    let doc =
        roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    let texts = doc.descendants().filter(|n| n.has_tag_name("text")).count();
    assert!(texts > 5, "{}: axis labels are text", path.display());
}

/// Number of frames of a GIF, which must decode.
fn gif_frames(path: &Path) -> usize {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options.read_info(fs::File::open(path).unwrap()).unwrap();
    let mut frames = 0;
    while decoder.read_next_frame().unwrap().is_some() {
        frames += 1;
    }
    frames
}

fn pictures(dir: &Path) -> Vec<Vec<u8>> {
    PICTURES
        .iter()
        .map(|p| fs::read(dir.join(p)).unwrap())
        .collect()
}

#[test]
fn every_case_draws_valid_pictures_that_plot_redraws_and_that_change_nothing() {
    let cases = case_files();
    assert!(!cases.is_empty());
    for case in cases {
        let name = case.display().to_string();
        let out = shared_run(&case, &[]);
        for p in PICTURES {
            let path = out.join(p);
            assert!(fs::metadata(&path).unwrap().len() > 0, "{name}: {p}");
            match path.extension().unwrap().to_str().unwrap() {
                "png" => assert_png(&path),
                "svg" => assert_svg(&path),
                _ => {
                    assert!(gif_frames(&path) > 1, "{name}: animated");
                    assert!(
                        fs::metadata(&path).unwrap().len() < 5 << 20,
                        "{name}: < 5 MB"
                    );
                }
            }
        }
        let frames = fs::read_to_string(out.join("frames.csv")).unwrap();
        assert!(
            frames.starts_with("frame,step,u,x,y,accumulated_shear\n"),
            "{name}"
        );

        // `soilcut plot` redraws the same files from the run's files.
        let drawn = pictures(&out);
        let tmp = tempfile::tempdir().unwrap();
        let shared = out;
        let out = tmp.path().join("drawn");
        copy_dir(&shared, &out);
        for p in PICTURES {
            fs::remove_file(out.join(p)).unwrap();
        }
        assert_ok(&soilcut(&["plot", out.to_str().unwrap()], tmp.path()));
        let redrawn = pictures(&out);
        for (i, p) in PICTURES.iter().enumerate() {
            assert!(drawn[i] == redrawn[i], "{name}: {p} differs when redrawn");
        }

        // Drawing does not change the results.
        let bare = shared_run(&case, &["--no-plots"]);
        assert!(!bare.join("plots").exists() && !bare.join("animation.gif").exists());
        for file in ["history.csv", "profile.csv", "frames.csv"] {
            assert!(
                fs::read(out.join(file)).unwrap() == fs::read(bare.join(file)).unwrap(),
                "{name}: {file} differs with --no-plots"
            );
        }
    }
}

#[test]
fn compare_overlays_runs_and_a_measured_curve() {
    let tmp = tempfile::tempdir().unwrap();
    let case = workspace().join("cases/paper/original.toml");
    let (a, b) = (shared_run(&case, &["--no-plots"]), tmp.path().join("b"));
    let a = a.to_str().unwrap();
    let title = "title=\"Original model, peak 38\"";
    run_short(
        &case,
        &b,
        &[
            "--no-plots",
            "--set",
            "soil.friction.peak=38",
            "--set",
            title,
        ],
    );
    fs::write(
        tmp.path().join("m.csv"),
        "u,force\n0,1000\n10,1800\n20,2500\n",
    )
    .unwrap();
    for out in ["cmp.png", "cmp.svg"] {
        let o = soilcut(
            &["compare", a, "b", "--measured", "m.csv", "--out", out],
            tmp.path(),
        );
        assert_ok(&o);
        let path = tmp.path().join(out);
        if out.ends_with(".png") {
            assert_png(&path);
        } else {
            assert_svg(&path);
            let text = fs::read_to_string(&path).unwrap();
            assert!(
                text.contains("measured (m.csv)"),
                "legend names the measured file"
            );
            assert!(
                text.contains("Original model"),
                "legend names the runs' titles"
            );
        }
    }
    let o = soilcut(&["compare", a, "--out", "cmp.pdf"], tmp.path());
    assert_eq!(o.status.code(), Some(2), "only .png and .svg");
    assert!(!tmp.path().join("cmp.pdf").exists());
    let o = soilcut(&["compare", a, "--measured", "nope.csv"], tmp.path());
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn compare_names_runs_of_one_title_by_their_folders() {
    let tmp = tempfile::tempdir().unwrap();
    let case = workspace().join("cases/paper/original.toml");
    let (a, b) = (tmp.path().join("coarse"), tmp.path().join("fine"));
    run_short(&case, &a, &["--no-plots"]);
    run_short(&case, &b, &["--no-plots", "--set", "run.increment=0.1"]);
    assert_ok(&soilcut(
        &["compare", "coarse", "fine", "--out", "c.svg"],
        tmp.path(),
    ));
    let text = fs::read_to_string(tmp.path().join("c.svg")).unwrap();
    assert!(
        text.contains("\ncoarse\n") && text.contains("\nfine\n"),
        "legend by folder"
    );
    assert!(!text.contains("Original model"), "not by the shared title");
}

#[test]
fn an_ensemble_writes_its_members_and_their_envelope() {
    let tmp = tempfile::tempdir().unwrap();
    let case = workspace().join("cases/paper/table1-s.toml");
    let case = case.to_str().unwrap();
    let mut args = vec![
        "run",
        case,
        "--ensemble",
        "3",
        "--jobs",
        "2",
        "--out",
        "ens",
    ];
    args.extend(SHORT);
    assert_ok(&soilcut(&args, tmp.path()));
    let ens = tmp.path().join("ens");
    for k in ["k-1", "k+0", "k+1"] {
        for picture in PICTURES {
            assert!(ens.join(k).join(picture).is_file(), "{k}/{picture}");
        }
    }
    assert_png(&ens.join("plots/envelope.png"));
    assert_svg(&ens.join("plots/envelope.svg"));
    let csv = fs::read_to_string(ens.join("ensemble.csv")).unwrap();
    assert!(csv.starts_with("u_over_d_from,u_over_d_to,members,mean,std,min,max,k-1,k+0,k+1\n"));
    // Member k = 0 is `soilcut run` of the case itself, bit for bit.
    let plain = shared_run(Path::new(case), &["--no-plots"]);
    let history = |dir: &Path| fs::read(dir.join("history.csv")).unwrap();
    assert_eq!(history(&ens.join("k+0")), history(&plain));
    // One thread: the same files.
    let mut one = vec!["run", case, "--ensemble", "3", "--jobs", "1", "--no-plots"];
    one.extend(["--out", "one"]);
    one.extend(SHORT);
    assert_ok(&soilcut(&one, tmp.path()));
    for name in [
        "ensemble.csv",
        "summary.json",
        "k+1/history.csv",
        "k-1/profile.csv",
    ] {
        let read = |d: &str| fs::read(tmp.path().join(d).join(name)).unwrap();
        assert_eq!(read("ens"), read("one"), "{name}");
    }
    // Bad input: one member, and --jobs without --ensemble.
    let o = soilcut(
        &["run", case, "--ensemble", "1", "--out", "bad"],
        tmp.path(),
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("at least 2 members"));
    assert!(!tmp.path().join("bad").exists(), "nothing written");
    let o = soilcut(&["run", case, "--jobs", "2", "--out", "bad"], tmp.path());
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn accuracy_judges_one_ensemble_folder_against_another() {
    let tmp = tempfile::tempdir().unwrap();
    let case = workspace().join("cases/paper/original.toml");
    let case = case.to_str().unwrap();
    let ensemble = |out: &str, extra: &[&str]| {
        let mut args = vec![
            "run",
            case,
            "--ensemble",
            "3",
            "--no-plots",
            "-q",
            "--out",
            out,
        ];
        args.extend(SHORT);
        args.extend(extra);
        assert_ok(&soilcut(&args, tmp.path()));
    };
    ensemble("a", &[]);
    ensemble("fine", &["--set", "run.increment=0.1"]);
    ensemble("long", &["--set", "run.travel=40"]);
    // Against itself: every deviation 0, accurate.
    let o = soilcut(&["accuracy", "a", "a", "--json"], tmp.path());
    assert_ok(&o);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["accurate"], true);
    assert_eq!(v["whole_run"]["deviation"], 0.0);
    let windows = v["windows"].as_array().unwrap();
    assert_eq!(windows.len(), 1);
    // Every row of the table: the window, both ensembles' mean and sd.
    let w = &windows[0];
    assert_eq!(
        (&w["u_over_d_from"], &w["u_over_d_to"]),
        (&0.into(), &1.into())
    );
    assert!(w["scheme"]["mean"].as_f64().unwrap() > 0.0, "{w}");
    assert_eq!(w["scheme"], w["reference"], "{w}");
    assert!(v["whole_run"]["reference"]["std"].is_f64(), "{v}");
    assert!(v["rule"].is_string(), "{v}");
    // Against a finer ensemble: the table names the rule and a verdict.
    let o = soilcut(&["accuracy", "a", "fine"], tmp.path());
    assert_ok(&o);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("rule: ") && text.contains("accurate: "),
        "{text}"
    );
    // Bad input: another travel, a folder without an ensemble.
    let o = soilcut(&["accuracy", "long", "a"], tmp.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("same travel"));
    let o = soilcut(&["accuracy", "a/k+0", "a"], tmp.path());
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.starts_with("error: a/k+0: a run folder, not an ensemble folder"),
        "{err}"
    );
    let o = soilcut(&["accuracy", "a", "nowhere"], tmp.path());
    assert!(String::from_utf8_lossy(&o.stderr).starts_with("error: nowhere: no such folder"));
}

#[test]
fn plot_of_a_folder_without_a_run_is_bad_input() {
    let tmp = tempfile::tempdir().unwrap();
    let o = soilcut(&["plot", "."], tmp.path());
    assert_eq!(o.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        stderr.starts_with("error: ") && stderr.lines().count() == 1,
        "{stderr}"
    );
}

#[test]
fn quiet_run_prints_nothing() {
    let tmp = tempfile::tempdir().unwrap();
    let case = workspace().join("cases/paper/original.toml");
    let out = tmp.path().join("q");
    run_short(&case, &out, &["--no-plots", "--quiet"]);
    let o = soilcut(
        &[
            "run",
            case.to_str().unwrap(),
            "--out",
            "q2",
            "--no-plots",
            "--quiet",
            "--set",
            "run.travel=1",
        ],
        tmp.path(),
    );
    assert_ok(&o);
    assert!(
        o.stdout.is_empty() && o.stderr.is_empty(),
        "no progress bar off a terminal"
    );
}

/// The rake is drawn: the inclined case's deformation picture and
/// animation differ from the same case with a vertical blade, whose blade
/// is a rectangle where the inclined one is a polygon (the plate's
/// geometry is tested in `soilcut-plot`).
#[test]
fn an_inclined_blade_is_drawn_inclined() {
    let tmp = tempfile::tempdir().unwrap();
    let case = workspace().join("cases/tools/inclined.toml");
    let (raked, vertical) = (shared_run(&case, &[]), tmp.path().join("vertical"));
    run_short(&case, &vertical, &["--set", "blade.rake=90"]);
    let resolved = fs::read_to_string(raked.join("case.resolved.toml")).unwrap();
    assert!(resolved.contains("rake = 60"), "{resolved}");
    for p in [
        "plots/deformation.png",
        "plots/deformation.svg",
        "animation.gif",
    ] {
        assert!(
            fs::read(raked.join(p)).unwrap() != fs::read(vertical.join(p)).unwrap(),
            "{p} shows the rake"
        );
    }
    let svg = |dir: &Path| fs::read_to_string(dir.join("plots/deformation.svg")).unwrap();
    let polygons = |text: &str| text.matches("<polygon").count();
    assert!(
        polygons(&svg(&raked)) > polygons(&svg(&vertical)),
        "the plate is a polygon"
    );
}
