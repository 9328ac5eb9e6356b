//! Fuzz the claim reader and the answer: any bytes give a claim or a typed error, never a
//! panic; an accepted claim is answered without a panic (at a capped precision, so one
//! input cannot run for long).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(mut claim) = penner::oracle::claim::parse(text, "fuzz") {
        assert!(claim.surface.validate().is_ok());
        if claim.surface.mesh.n_faces() <= 64 {
            claim.max_bits = claim.max_bits.min(256);
            if let Ok(answer) = penner::oracle::certify::certify(&claim) {
                // A refutation always names its first counterexample.
                let refuted = answer.verdict == penner::oracle::certify::ClaimVerdict::Refuted;
                assert_eq!(refuted, answer.counterexample.is_some());
            }
        }
    }
});
