//! Fuzz the off surface reader: any bytes give a surface or a typed error, never a panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(s) = penner::io::off::read_bytes(data) {
        // A surface that was accepted is valid.
        assert!(s.validate().is_ok());
        assert!(s.mesh.check_invariants().is_ok());
    }
});
