//! Definition 2 (T35): scalings + Ptolemy flips ⇔ same shear data, exactly over ℚ, with a
//! negative control.

use penner::geometry::scaling::reconstruct_scale_factors;
use penner::mesh::{builders, Edge, Mesh};
use penner::theorems::t35_definition_two::{
    check_definition_two_exact, ptolemy_flips_exact, scaled_then_flipped_exact,
};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Rational;

fn surfaces() -> Vec<(&'static str, Mesh)> {
    vec![
        ("octahedron", builders::octahedron().mesh),
        ("tetrahedron", builders::tetrahedron().mesh),
        ("one-vertex torus", builders::one_vertex_torus()),
    ]
}

/// A random sequence of `n` flips the mesh accepts (each tried on a scratch copy).
fn flip_sequence(m: &Mesh, n: usize, rng: &mut ChaCha8Rng) -> Vec<Edge> {
    let mut scratch = m.clone();
    let mut seq = Vec::new();
    for _ in 0..20 * n {
        if seq.len() == n {
            break;
        }
        let e = Edge(rng.gen_range(0..u32::try_from(m.n_edges()).unwrap()));
        if scratch.flip(e).is_ok() {
            seq.push(e);
        }
    }
    assert_eq!(seq.len(), n, "no flip sequence of length {n}");
    seq
}

fn random_rationals(n: usize, lo: i32, hi: i32, rng: &mut ChaCha8Rng) -> Vec<Rational> {
    (0..n)
        .map(|_| Rational::from((rng.gen_range(lo..hi), rng.gen_range(lo..hi))))
        .collect()
}

#[test]
fn t35_definition_two_scalings_and_flips_iff_same_shear_data() {
    let mut rng = ChaCha8Rng::seed_from_u64(35);
    for (name, m) in surfaces() {
        for n_flips in [0, 1, 3, 6] {
            let flips = flip_sequence(&m, n_flips, &mut rng);
            let l = random_rationals(m.n_edges(), 10, 20, &mut rng);
            let s = random_rationals(m.n_vertices(), 1, 9, &mut rng);
            let (mb, lb) = scaled_then_flipped_exact(&m, &l, &s, &flips).unwrap();
            let v = check_definition_two_exact(&m, &l, &flips, &lb);
            assert!(v.holds(), "{name} {flips:?}: {v:?}");
            // The reconstructed factors are the chosen ones: e^{u_v} = s_v².
            let (ma, la) = ptolemy_flips_exact(&m, &l, &flips).unwrap();
            assert_eq!(ma.face_list(), mb.face_list());
            let exp_u = reconstruct_scale_factors(&ma, &la, &lb).exp_u();
            for (x, sv) in exp_u.iter().zip(&s) {
                assert_eq!(x.clone(), Some(Rational::from(sv.square_ref())), "{name}");
            }
            // Negative control: perturb one length of B by 1/1000: the same check fails.
            let mut bad = lb.clone();
            let k = rng.gen_range(0..bad.len());
            bad[k] += Rational::from((1, 1000));
            let v = check_definition_two_exact(&m, &l, &flips, &bad);
            assert!(
                v.fails(),
                "{name} {flips:?}: perturbed edge {k} passed: {v:?}"
            );
        }
    }
}

#[test]
fn t35_negative_control_unscaled_metric_with_other_shears_fails() {
    // Tetrahedron: B = the Ptolemy transport of a metric with different cross ratios.
    let m = builders::tetrahedron().mesh;
    let l: Vec<Rational> = (0..6).map(|_| Rational::from(1)).collect();
    let mut other = l.clone();
    other[0] = Rational::from(2);
    let flips = [Edge(1)];
    let (_, lb) = ptolemy_flips_exact(&m, &other, &flips).unwrap();
    assert!(check_definition_two_exact(&m, &l, &flips, &lb).fails());
    let (_, lb) = ptolemy_flips_exact(&m, &l, &flips).unwrap();
    assert!(check_definition_two_exact(&m, &l, &flips, &lb).holds());
}
