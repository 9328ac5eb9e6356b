//! Argument reduction `x = k·π/2 + r`, `|r| ≤ π/4`, for every finite double-double `x`
//! (Payne–Hanek): each word `w = m·2ᵉ` (`m` a 53-bit integer) is multiplied in integer
//! arithmetic by the 320 bits of 2/π that matter for `w·(2/π) mod 4`, the two results are
//! added in 256-bit fixed point (units 2⁻²⁵⁴, so arithmetic mod 2²⁵⁶ is arithmetic mod 4),
//! the nearest integer `k` is removed, and the fraction is multiplied by π/2 to 128 bits.
//! Absolute error of `r` ≤ 2⁻²⁵², relative error ≤ u²(1 + 2⁻¹⁹) on top. proof: B18

use super::arith::fast_two_sum;
use super::Dd;

/// The first 1536 bits of 2/π: bit `j` (weight 2⁻ʲ, `j ≥ 1`) is bit `63 − (j−1) mod 64`
/// of word `(j−1) / 64`. Checked against MPFR by `b18_two_over_pi_table_matches_mpfr`.
#[doc(hidden)]
pub const TWO_OVER_PI_BITS: [u64; 24] = [
    0xa2f9836e4e441529,
    0xfc2757d1f534ddc0,
    0xdb6295993c439041,
    0xfe5163abdebbc561,
    0xb7246e3a424dd2e0,
    0x06492eea09d1921c,
    0xfe1deb1cb129a73e,
    0xe88235f52ebb4484,
    0xe99c7026b45f7e41,
    0x3991d639835339f4,
    0x9c845f8bbdf9283b,
    0x1ff897ffde05980f,
    0xef2f118b5a0a6d1f,
    0x6d367ecf27cb09b7,
    0x4f463f669e5fea2d,
    0x7527bac7ebe5f17b,
    0x3d0739f78a5292ea,
    0x6bfb5fb11f8d5d08,
    0x56033046fc7b6bab,
    0xf0cfbc209af4361d,
    0xa9e391615ee61b08,
    0x6599855f14a06840,
    0x8dffd8804d732731,
    0x06061556ca73a8c9,
];

/// `⌊π/2 · 2¹²⁷⌋`. Checked against MPFR by `b18_two_over_pi_table_matches_mpfr`.
#[doc(hidden)]
pub const PI_2_FIXED: u128 = 0xc90fdaa22168c234c4c6628b80dc1cd1;

/// A 256-bit number, least significant limb first.
type U256 = [u64; 4];

/// The 320 bits `b_j … b_{j+319}` of 2/π as five limbs, most significant first.
fn window(j: usize) -> [u64; 5] {
    let off = j - 1;
    let (i, sh) = (off / 64, off % 64);
    let t = |k: usize| TWO_OVER_PI_BITS.get(i + k).copied().unwrap_or(0);
    let mut w = [0u64; 5];
    for (k, wk) in w.iter_mut().enumerate() {
        *wk = if sh == 0 {
            t(k)
        } else {
            (t(k) << sh) | (t(k + 1) >> (64 - sh))
        };
    }
    w
}

/// `|w|·(2/π) mod 4` in units of 2⁻²⁵⁴, rounded down (error in `[0, 1 + 2⁻¹¹)` units).
fn word_times_two_over_pi(w: f64) -> U256 {
    let bits = w.abs().to_bits();
    let biased = (bits >> 52) & 0x7ff;
    let frac = bits & ((1u64 << 52) - 1);
    let (m, e) = if biased == 0 {
        (frac, -1074_i64)
    } else {
        (frac | (1u64 << 52), biased as i64 - 1075)
    };
    if m == 0 {
        return [0; 4];
    }
    // Bits b_j with j ≤ e − 2 contribute multiples of 4; start the window at j0.
    let j0 = (e - 1).max(1);
    let s = j0 + 65 - e; // value = (m · W) >> s, in units of 2⁻²⁵⁴
    let wnd = window(j0 as usize);
    // m · W as six limbs, least significant first.
    let mut p = [0u64; 6];
    let mut carry: u128 = 0;
    for k in 0..5 {
        let t = u128::from(m) * u128::from(wnd[4 - k]) + carry;
        p[k] = t as u64;
        carry = t >> 64;
    }
    p[5] = carry as u64;
    shift_right_low256(&p, s as usize)
}

/// `(p >> s) mod 2²⁵⁶` for a 384-bit `p` (least significant limb first).
fn shift_right_low256(p: &[u64; 6], s: usize) -> U256 {
    let (limb, sh) = (s / 64, s % 64);
    let get = |k: usize| p.get(k).copied().unwrap_or(0);
    let mut out = [0u64; 4];
    for (k, o) in out.iter_mut().enumerate() {
        let lo = get(k + limb);
        *o = if sh == 0 {
            lo
        } else {
            (lo >> sh) | (get(k + limb + 1) << (64 - sh))
        };
    }
    out
}

fn add256(a: U256, b: U256) -> U256 {
    let mut out = [0u64; 4];
    let mut c = false;
    for k in 0..4 {
        let (s1, c1) = a[k].overflowing_add(b[k]);
        let (s2, c2) = s1.overflowing_add(u64::from(c));
        out[k] = s2;
        c = c1 || c2;
    }
    out
}

fn neg256(a: U256) -> U256 {
    add256([!a[0], !a[1], !a[2], !a[3]], [1, 0, 0, 0])
}

/// `x·(2/π) mod 4` in units of 2⁻²⁵⁴ (two's complement for negative words).
fn times_two_over_pi(x: Dd) -> U256 {
    let part = |w: f64| {
        let v = word_times_two_over_pi(w);
        if w < 0.0 {
            neg256(v)
        } else {
            v
        }
    };
    add256(part(x.hi), part(x.lo))
}

/// A 128-bit `t ≠ 0` times `2^scale`, as the double-word nearest to it given its leading
/// word (relative error ≤ u²).
fn u128_to_dd(t: u128, scale: i32) -> Dd {
    let lz = t.leading_zeros();
    let t = t << lz;
    let scale = scale - lz as i32;
    let c1 = (t >> 75) as u64 as f64;
    let c2 = ((t >> 22) & ((1u128 << 53) - 1)) as u64 as f64;
    let c3 = (t & ((1u128 << 22) - 1)) as u64 as f64;
    let (h, l) = fast_two_sum(c1 * 2f64.powi(53), c2);
    let (hi, lo) = fast_two_sum(h, l + c3 * 2f64.powi(-22));
    Dd { hi, lo }.ldexp(scale + 22)
}

/// `x = k·π/2 + r` with `|r| ≤ π/4 (1 + 2⁻¹⁰⁰)`: returns `r` and `k mod 4`, for every
/// finite `x`. proof: B18
pub(crate) fn reduce_payne_hanek(x: Dd) -> (Dd, i64) {
    let v = times_two_over_pi(x);
    // k = nearest integer to v·2⁻²⁵⁴: add one half (2²⁵³ units), read the top two bits.
    let t = add256(v, [0, 0, 0, 1u64 << 61]);
    let k = (t[3] >> 62) as i64;
    // f = v − k·2²⁵⁴ ∈ [−2²⁵³, 2²⁵³) in two's complement.
    let f = add256(v, [0, 0, 0, (k as u64).wrapping_neg() << 62]);
    let negative = f[3] >> 63 == 1;
    let mag = if negative { neg256(f) } else { f };
    let Some(top) = (0..4).rev().find(|&i| mag[i] != 0) else {
        return (Dd::from_f64(0.0), k);
    };
    // Leading 128 bits of |f|: |f| ≈ lead · 2^(shift) units.
    let lead_bit = 64 * top as i32 + 63 - mag[top].leading_zeros() as i32;
    let shift = lead_bit - 127;
    let lead = if shift >= 0 {
        let w = shift_right_low256(&[mag[0], mag[1], mag[2], mag[3], 0, 0], shift as usize);
        u128::from(w[0]) | (u128::from(w[1]) << 64)
    } else {
        // |f| < 2¹²⁷ units: it fits in the two low limbs.
        (u128::from(mag[0]) | (u128::from(mag[1]) << 64)) << (-shift)
    };
    // r = lead · 2^(shift − 254) · π/2 = lead · PI_2_FIXED · 2^(shift − 381).
    let (ph, _) = mul_u128(lead, PI_2_FIXED);
    let r = u128_to_dd(ph, shift - 381 + 128);
    (if negative { -r } else { r }, k)
}

/// The 256-bit product of two 128-bit numbers as (high, low) halves.
fn mul_u128(a: u128, b: u128) -> (u128, u128) {
    let mask = u128::from(u64::MAX);
    let (a1, a0) = (a >> 64, a & mask);
    let (b1, b0) = (b >> 64, b & mask);
    let p00 = a0 * b0;
    let p01 = a0 * b1;
    let p10 = a1 * b0;
    let p11 = a1 * b1;
    let mid = (p00 >> 64) + (p01 & mask) + (p10 & mask);
    let lo = (p00 & mask) | (mid << 64);
    let hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    (hi, lo)
}
