//! Fuzz the exact number parser: any string gives a rational or a typed error.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(s) = std::str::from_utf8(data) {
        let _ = penner::scalar::parse_rational(s);
    }
});
