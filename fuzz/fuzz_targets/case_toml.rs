//! Fuzz target: any bytes as a case file (soilcut_io::parse_case_bytes).
//! The body, and what it asserts, is soilcut_fuzz_bodies::case_toml.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    soilcut_fuzz_bodies::case_toml(data);
});
