//! The drawing library on made-up runs: files appear, drawing is
//! deterministic, and no system font machinery is linked.

use soilcut_plot::{
    draw_animation, draw_compare, draw_deformation, draw_run, Format, Frame, Increment, Measured,
    RunData, SurfacePoint,
};
use std::fs;
use std::path::Path;

/// A run with a pile growing in front of a blade moving 2 d.
fn run(band_width: f64) -> RunData {
    let d = 10.0;
    let history: Vec<Increment> = (0..100)
        .map(|i| {
            let u = i as f64 * 0.2;
            Increment {
                step: i + 1,
                u,
                force_norm: 1.3 + 0.02 * i as f64 + if i % 30 == 0 { 0.5 } else { 0.0 },
                beta_deg: 20.0 + (i % 30) as f64 * 0.3,
                x_emergence: u + 25.0 - (i % 30) as f64 * 0.2,
                y_emergence: 2.0,
                depth: d,
            }
        })
        .collect();
    let surface = |u: f64, h: f64| -> Vec<SurfacePoint> {
        (0..400)
            .map(|k| {
                let x = u + k as f64 * 0.2;
                SurfacePoint {
                    x,
                    y: (h - 0.3 * (x - u)).max(0.0),
                    accumulated_shear: if k % 50 == 0 { 3.0 } else { 0.1 },
                }
            })
            .collect()
    };
    let frames = (0..=10)
        .map(|f| Frame {
            step: f * 10,
            u: f as f64 * 2.0,
            surface: surface(f as f64 * 2.0, f as f64),
        })
        .collect();
    RunData {
        title: "A made-up run".into(),
        depth: d,
        rake: 90.0,
        unit_weight: 1.0,
        band_width,
        history,
        profile: surface(20.0, 10.0),
        frames,
        ridges: Vec::new(),
    }
}

fn read_all(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let p = e.unwrap().path();
            (p.display().to_string(), fs::read(&p).unwrap())
        })
        .collect();
    files.sort();
    files
}

#[test]
fn run_pictures_are_written_and_deterministic() {
    for band_width in [0.0, 1.5] {
        let tmp = tempfile::tempdir().unwrap();
        let written = draw_run(&run(band_width), &tmp.path().join("a")).unwrap();
        assert_eq!(written.len(), 6);
        draw_run(&run(band_width), &tmp.path().join("b")).unwrap();
        let (a, b) = (
            read_all(&tmp.path().join("a")),
            read_all(&tmp.path().join("b")),
        );
        assert_eq!(a.len(), 6);
        for ((_, x), (name, y)) in a.iter().zip(&b) {
            assert!(
                !x.is_empty() && x == y,
                "{name} is the same when drawn again"
            );
        }
        let png = &a
            .iter()
            .find(|f| f.0.ends_with("deformation.png"))
            .unwrap()
            .1;
        assert_eq!(&png[1..4], b"PNG");
        assert!(
            png.windows(4).any(|w| w == b"pHYs"),
            "the PNG states its dpi"
        );
    }
}

#[test]
fn animation_and_comparison() {
    let tmp = tempfile::tempdir().unwrap();
    let gif = tmp.path().join("a.gif");
    draw_animation(&run(0.0), &gif).unwrap();
    assert_eq!(&fs::read(&gif).unwrap()[..6], b"GIF89a");
    let mut no_frames = run(0.0);
    no_frames.frames.clear();
    assert!(draw_animation(&no_frames, &gif).is_err());

    let measured = Measured {
        label: "measured".into(),
        points: vec![(0.0, 100.0), (10.0, 200.0)],
    };
    let runs = [run(0.0), run(1.5)];
    for name in ["c.png", "c.svg"] {
        draw_compare(&runs, Some(&measured), &tmp.path().join(name)).unwrap();
    }
    let e = draw_compare(&runs, None, &tmp.path().join("c.jpg")).unwrap_err();
    assert!(e.message.contains(".png or .svg"), "{e}");
    assert!(draw_compare(&[], None, &tmp.path().join("d.png")).is_err());
    assert_eq!(Format::of(Path::new("x.SVG")).unwrap(), Format::Svg);
}

/// The pixels of the PNG at `path` that are exactly `rgb`.
fn pixels_of(path: &Path, rgb: [u8; 3]) -> usize {
    let decoder = png::Decoder::new(std::io::BufReader::new(fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf[..info.buffer_size()]
        .chunks(3)
        .filter(|p| *p == rgb)
        .count()
}

/// One run compared with itself: the first curve, drawn wider, shows on
/// both sides of the second along the whole run (a curve of one width
/// hid it entirely; the legend's mark alone is 200 pixels).
#[test]
fn compared_runs_that_coincide_stay_visible() {
    let tmp = tempfile::tempdir().unwrap();
    let path = tmp.path().join("c.png");
    draw_compare(&[run(0.0), run(0.0)], None, &path).unwrap();
    let first = pixels_of(&path, [31, 119, 180]);
    assert!(first > 3000, "{first} pixels of the first run's colour");
}

/// A long run's ground, to equal scales over 30 d, is a strip: the
/// picture adds the ground near the blade to scales of its own. A short
/// run's is not, and has no such panel.
#[test]
fn a_long_run_shows_the_ground_near_the_blade_too() {
    let tmp = tempfile::tempdir().unwrap();
    let mut long = run(0.0);
    // A band emerged 30 d ahead: the ground there moved by 0.01 d.
    let far = long.profile.last().unwrap().x + 1.0;
    long.profile.extend((0..1500).map(|k| SurfacePoint {
        x: far + k as f64 * 0.2,
        y: if k == 1499 { 0.1 } else { 0.0 },
        accumulated_shear: 0.0,
    }));
    let near = "near the blade at the end of the run";
    for (data, expected) in [(run(0.0), false), (long, true)] {
        let path = tmp.path().join("d.svg");
        draw_deformation(&data, &path).unwrap();
        let svg = fs::read_to_string(&path).unwrap();
        assert_eq!(svg.contains(near), expected);
    }
}

/// `run` with the blade deepening from d/2 to d over its first d of travel.
fn deepening() -> RunData {
    let mut run = run(0.0);
    let d = run.depth;
    for h in &mut run.history {
        h.depth = d * (0.5 + 0.5 * (h.u / d).min(1.0));
    }
    run
}

/// A depth path is drawn: the deformation picture and the animation of a
/// deepening blade differ from those of the same run at a constant depth
/// (the geometry of the trench floor and the slip lines' starts is tested
/// in the library), and are deterministic too.
#[test]
fn a_deepening_blade_is_drawn_along_its_path() {
    let tmp = tempfile::tempdir().unwrap();
    let draw = |run: &RunData, name: &str| {
        let dir = tmp.path().join(name);
        draw_run(run, &dir).unwrap();
        draw_animation(run, &dir.join("a.gif")).unwrap();
        read_all(&dir)
    };
    let flat = draw(&run(0.0), "flat");
    let deep = draw(&deepening(), "deep");
    let again = draw(&deepening(), "again");
    for (((name, f), (_, x)), (_, y)) in flat.iter().zip(&deep).zip(&again) {
        assert!(x == y, "{name} is the same when drawn again");
        let differs = ["deformation.png", "deformation.svg", "a.gif"]
            .iter()
            .any(|n| name.ends_with(n));
        let same = ["force.png", "beta.png"].iter().any(|n| name.ends_with(n));
        if differs {
            assert!(f != x, "{name} shows the depth path");
        } else if same {
            assert!(f == x, "{name} does not depend on the path");
        }
    }
}

/// Fonts are bundled: nothing may bring in plotters' `ttf` feature, which
/// loads system fonts through font-kit (criterion's default features would).
#[test]
fn no_system_font_crates_are_locked() {
    let lock =
        fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../../Cargo.lock")).unwrap();
    for name in ["font-kit", "yeslogic-fontconfig-sys", "servo-fontconfig"] {
        assert!(
            !lock.contains(&format!("name = \"{name}\"")),
            "{name} is in Cargo.lock"
        );
    }
}
