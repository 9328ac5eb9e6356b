//! Fuzz the failure-file reader: any bytes give a failure or a typed error, never a panic;
//! an accepted file survives a write/read round trip unchanged.
#![no_main]

use penner::oracle::failure::Failure;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(f) = Failure::parse(text, "fuzz") {
        let again = Failure::parse(&f.to_json().to_string(), "round trip")
            .expect("a written failure file reads back");
        assert_eq!(again.check, f.check);
        assert_eq!(again.precision, f.precision);
        assert_eq!(again.surface.mesh, f.surface.mesh);
        assert_eq!(again.surface.metric, f.surface.metric);
        assert_eq!(again.witnesses.len(), f.witnesses.len());
    }
});
