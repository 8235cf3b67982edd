//! Fuzz target: the bytes as a sequence of C ABI calls (soilcut-ffi) with
//! arbitrary arguments. The body, and what it asserts, is
//! soilcut_fuzz_bodies::ffi_calls.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    soilcut_fuzz_bodies::ffi_calls(data);
});
