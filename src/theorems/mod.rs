//! Read-only checks, one per catalogue ID (MATH.md). Checks never mutate and never panic;
//! a failing check lists *all* failing elements.

pub mod bounds;
pub mod inputs;
pub mod report;
pub mod verdict;

pub use verdict::{Settings, Verdict, Witness};
pub mod t01_gauss_bonnet;
pub mod t03_angle_rigidity;
pub mod t04_angle_integrability;
pub mod t05_cotan_laplacian;
pub mod t05_semidefinite;
pub mod t07_conformal_energy;
pub mod t08_circle_pattern_lengths;
pub mod t09_circle_pattern_rigidity;
pub mod t10_thurston_existence;
pub mod t13_chow_luo_flow;
pub mod t15_lemma1;
pub mod t16_scaling_cross_ratios;
pub mod t17_cross_ratio_equivalence;
pub mod t18_two_triangle_sphere;
pub mod t19_one_vertex_torus;
pub mod t20_mobius_cross_ratios;
pub mod t21_delaunay_flipping;
pub mod t22_delaunay_uniqueness;
pub mod t23_euclidean_flip_cone_metric;
pub mod t27_shear_log_cross_ratio;
pub mod t28_ptolemy_flip;
pub mod t29_euclidean_ptolemy_cocircular;
pub mod t30_lobachevsky;
pub mod t34_steiner_rivin;
pub mod t35_definition_two;
pub mod t36_harmonic_embedding;
