//! The output folder's placement, one process.

use super::*;

fn files() -> Vec<(&'static str, String)> {
    vec![("a.txt", "new".to_string())]
}

#[test]
fn writes_and_refuses_to_overwrite() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("nested/out");
    write_output_dir(&dir, &files(), false).unwrap();
    assert_eq!(fs::read_to_string(dir.join("a.txt")).unwrap(), "new");
    let e = write_output_dir(&dir, &files(), false).unwrap_err();
    assert!(matches!(e, OutputError::Exists(_)));
    fs::write(dir.join("stale.txt"), "x").unwrap();
    write_output_dir(&dir, &files(), true).unwrap();
    assert!(!dir.join("stale.txt").exists(), "force replaces the folder");
    let leftovers: Vec<_> = fs::read_dir(dir.parent().unwrap()).unwrap().collect();
    assert_eq!(leftovers.len(), 1, "no staging folders left behind");
}

#[test]
fn force_replaces_only_what_soilcut_wrote() {
    let tmp = tempfile::tempdir().unwrap();
    let file = tmp.path().join("notes.txt");
    fs::write(&file, "mine").unwrap();
    let foreign = tmp.path().join("mine");
    fs::create_dir(&foreign).unwrap();
    fs::write(foreign.join("notes.txt"), "mine").unwrap();
    for force in [false, true] {
        let e = write_output_dir(&file, &files(), force).unwrap_err();
        assert!(matches!(e, OutputError::NotAFolder(_)), "{e:?}");
        assert!(e.to_string().contains("not a folder"), "{e}");
    }
    let e = write_output_dir(&foreign, &files(), true).unwrap_err();
    assert!(matches!(e, OutputError::NotOurs(_)), "{e:?}");
    assert_eq!(fs::read_to_string(&file).unwrap(), "mine");
    assert_eq!(
        fs::read_to_string(foreign.join("notes.txt")).unwrap(),
        "mine"
    );
    let ours = tmp.path().join("ours");
    write_output_dir(&ours, &files(), false).unwrap();
    assert!(ours.join(OUTPUT_MARKER).is_file());
    write_output_dir(&ours, &files(), true).unwrap();
}

#[test]
fn unnamed_folders_are_refused() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("a");
    write_output_dir(&dir, &files(), false).unwrap();
    for unnamed in [dir.join(".."), PathBuf::from("/")] {
        let e = check_output_dir(&unnamed, true).unwrap_err();
        assert!(matches!(e, OutputError::Unnamed(_)), "{unnamed:?}");
        let e = OutputDir::claim(&unnamed, false).unwrap_err();
        assert!(matches!(e, OutputError::Unnamed(_)), "{unnamed:?}");
    }
    assert!(check_output_dir(&dir.join("."), true).is_ok(), "a/. is a");
    write_output_dir(&dir.join("."), &files(), true).unwrap();
}

#[test]
fn empty_folder_is_used() {
    let tmp = tempfile::tempdir().unwrap();
    write_output_dir(tmp.path(), &files(), false).unwrap();
    assert!(tmp.path().join("a.txt").exists());
}

#[test]
fn failure_leaves_nothing() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("out");
    let bad = vec![
        ("a.txt", "x".to_string()),
        ("no/such/b.txt", "y".to_string()),
    ];
    assert!(matches!(
        write_output_dir(&dir, &bad, false),
        Err(OutputError::Io { .. })
    ));
    assert_eq!(fs::read_dir(tmp.path()).unwrap().count(), 0);
}

#[test]
fn a_claimed_name_is_refused_to_a_second_claim_until_dropped() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("new/out");
    let first = OutputDir::claim(&dir, false).unwrap();
    let e = OutputDir::claim(&dir, false).unwrap_err();
    assert!(matches!(e, OutputError::Busy(_, Some(_))), "{e:?}");
    assert!(e.to_string().contains("another soilcut"), "{e}");
    drop(first);
    assert_eq!(fs::read_dir(tmp.path()).unwrap().count(), 0, "new/ removed");
}

#[test]
fn what_appears_at_the_destination_is_kept() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("out");
    for force in [false, true] {
        let claim = OutputDir::claim(&dir, force).unwrap();
        fs::create_dir_all(&dir).unwrap();
        if force {
            // soilcut's marker alone does not make a folder its own
            // after the claim: a folder absent then is never replaced.
            fs::write(dir.join("mine"), "").unwrap();
        }
        let e = claim.write_then(&files(), |_| Ok(())).unwrap_err();
        let OutputError::Appeared { kept, .. } = &e else {
            panic!("{e:?}")
        };
        assert!(kept.join("a.txt").is_file(), "{e}");
        fs::remove_dir_all(kept).unwrap();
        assert!(dir.is_dir(), "left alone");
    }
}

#[test]
fn force_swaps_only_soilcuts_folder() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("out");
    write_output_dir(&dir, &files(), false).unwrap();
    let claim = OutputDir::claim(&dir, true).unwrap();
    // Replaced by the user's own folder after the claim.
    fs::remove_dir_all(&dir).unwrap();
    fs::create_dir(&dir).unwrap();
    fs::write(dir.join("mine"), "").unwrap();
    let e = claim.write_then(&files(), |_| Ok(())).unwrap_err();
    assert!(matches!(e, OutputError::Appeared { .. }), "{e:?}");
    assert!(dir.join("mine").is_file());
}

#[test]
fn a_long_name_is_refused_before_anything_is_made() {
    let tmp = tempfile::tempdir().unwrap();
    let fits = tmp.path().join("n".repeat(MAX_NAME_BYTES));
    write_output_dir(&fits, &files(), false).unwrap();
    write_output_dir(&fits, &files(), true).unwrap();
    let long = tmp.path().join("m".repeat(MAX_NAME_BYTES + 1));
    let e = OutputDir::claim(&long, false).unwrap_err();
    assert!(matches!(e, OutputError::NameTooLong(_, 238)), "{e:?}");
    assert_eq!(fs::read_dir(tmp.path()).unwrap().count(), 1);
}

#[test]
fn runs_in_parallel_share_the_folder_they_make() {
    // A sweep's runs each claim `runs/run-N` at once; the first to make
    // `runs/` must not fail the others (CI lost a sweep to this race).
    for round in 0..20 {
        let tmp = tempfile::tempdir().unwrap();
        let parent = tmp.path().join(format!("deep-{round}/runs"));
        let written: Vec<_> = std::thread::scope(|s| {
            let spawned: Vec<_> = (0..8)
                .map(|i| {
                    let dir = parent.join(format!("run-{i}"));
                    s.spawn(move || write_output_dir(&dir, &files(), false))
                })
                .collect();
            spawned.into_iter().map(|h| h.join().unwrap()).collect()
        });
        for w in written {
            w.unwrap();
        }
        assert_eq!(fs::read_dir(&parent).unwrap().count(), 8);
    }
}
