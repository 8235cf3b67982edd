//! Fuzz target: --set arguments on a shipped case (Override, parse_case).
//! The body, and what it asserts, is soilcut_fuzz_bodies::set_override.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    soilcut_fuzz_bodies::set_override(data);
});
