//! Fuzz target: any bytes as a measured curve (soilcut_io::parse_measured_bytes).
//! The body, and what it asserts, is soilcut_fuzz_bodies::measured_csv.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    soilcut_fuzz_bodies::measured_csv(data);
});
