//! Seeded random streams.
//!
//! Every run owns one ChaCha8 stream derived from (seed, run index) and passes it explicitly as
//! `&mut rng`; nothing in tidepath reads a global or thread-local generator. Parallel
//! evaluation never draws random numbers, so results do not depend on the thread count.

use rand::{Rng as _, RngCore as _, SeedableRng};
use rand_chacha::ChaCha8Rng;

pub type Rng = ChaCha8Rng;

/// Fills `out` with uniform draws in [0, 1): the same values, from the same part of the
/// stream, as `out.len()` successive calls of `rng.random::<f64>()`, but drawn in bulk (the
/// generator's words are copied a block at a time instead of one call per value).
///
/// `random::<f64>()` takes one 64-bit word and keeps its 53 high bits; `fill` on `u64`s
/// hands out the same words in the same order, so the two can be mixed freely.
pub fn fill_unit_f64(rng: &mut Rng, out: &mut [f64]) {
    const CHUNK: usize = 32;
    let mut words = [0u64; CHUNK];
    for chunk in out.chunks_mut(CHUNK) {
        let words = &mut words[..chunk.len()];
        rng.fill(words);
        for (o, &w) in chunk.iter_mut().zip(words.iter()) {
            *o = unit_f64(w);
        }
    }
}

/// Fills `out` with uniform draws in (0, 1) at 32-bit resolution, `(w + 1/2) / 2^32` for
/// successive 32-bit words of the stream: two values per 64-bit word, so half the generator's
/// work of [`fill_unit_f64`]. For random steps (the fireflies' `rand − 0.5`), where 2^−32 is
/// far finer than any step needs and the generator is a large part of an iteration's cost.
pub fn fill_unit_f64_32(rng: &mut Rng, out: &mut [f64]) {
    const CHUNK: usize = 64;
    let mut words = [0u32; CHUNK];
    for chunk in out.chunks_mut(CHUNK) {
        let words = &mut words[..chunk.len()];
        fill_u32(rng, words);
        for (o, &w) in chunk.iter_mut().zip(words.iter()) {
            *o = unit_f64_32(w);
        }
    }
}

/// [`fill_unit_f64_32`]'s value for the 32-bit word `w`: `(w + 1/2) / 2^32`, exact.
#[inline(always)]
pub fn unit_f64_32(w: u32) -> f64 {
    const SCALE: f64 = 1.0 / 4_294_967_296.0;
    (f64::from(w) + 0.5) * SCALE
}

/// Fills `out` with the next `out.len()` 32-bit words of the stream: the same words, taking
/// the same part of the stream, as `rng.fill(out)`, but read two at a time with `next_u64`
/// (low half first, as the generator's buffer holds them) and an odd last one with `next_u32`.
/// `fill` goes through `fill_bytes`, which copies the words in four-byte chunks in a call that
/// is not inlined: for the 30 to 60 words of one jellyfish move that copy took about a third
/// of the time of generating them (perf, ijs on Rastrigin-30).
#[inline]
pub fn fill_u32(rng: &mut Rng, out: &mut [u32]) {
    let mut pairs = out.chunks_exact_mut(2);
    for pair in &mut pairs {
        let w = rng.next_u64();
        pair[0] = w as u32;
        pair[1] = (w >> 32) as u32;
    }
    if let [last] = pairs.into_remainder() {
        *last = rng.next_u32();
    }
}

/// `random::<f64>()`'s value for the word `w`: `(w >> 11) as f64 / 2^53`, computed with bit
/// operations that vectorize (x86-64 without AVX-512 has no vector integer-to-float
/// conversion, and the scalar one serialises the loop). Exact, hence the same bits: the low 52
/// bits `lo` of `k = w >> 11` become the double `2^52 + lo`, minus `2^52` is `lo`; the top bit
/// of `k` adds `0` or `2^52`; every step is exact below `2^53`, as is the final scaling.
#[inline(always)]
pub fn unit_f64(w: u64) -> f64 {
    const TWO52_BITS: u64 = 0x4330_0000_0000_0000; // 2^52 as a double
    const TWO52: f64 = (1u64 << 52) as f64;
    const SCALE: f64 = 1.0 / (1u64 << 53) as f64;
    let k = w >> 11;
    let lo = f64::from_bits(TWO52_BITS | (k & ((1 << 52) - 1))) - TWO52;
    let hi = f64::from_bits(TWO52_BITS & 0u64.wrapping_sub(k >> 52));
    (lo + hi) * SCALE
}

/// The stream of run `run` under master seed `seed`.
pub fn run_rng(seed: u64, run: u64) -> Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(run);
    rng
}

/// A stable 64-bit seed from a master seed and a list of labels (scenario, planner, ...).
///
/// Uses FNV-1a over the labels and SplitMix64 finalisation, both fixed forever, so a seed
/// printed in a results file can be reproduced by any later version of tidepath.
pub fn derive_seed(master: u64, labels: &[&str]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325 ^ splitmix64(master);
    for label in labels {
        for &b in label.as_bytes() {
            h ^= b as u64;
            h = h.wrapping_mul(0x0000_0100_0000_01b3);
        }
        // Separator so ("ab","c") and ("a","bc") differ.
        h ^= 0xff;
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    splitmix64(h)
}

fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two 32-bit draws per 64-bit word, low half first, strictly inside (0, 1), and the same
    /// values however the request is split.
    #[test]
    fn thirty_two_bit_draws_take_half_words() {
        let mut a = run_rng(5, 0);
        let mut b = a.clone();
        let mut out = vec![0.0; 100];
        fill_unit_f64_32(&mut a, &mut out);
        let words: Vec<u64> = (0..50).map(|_| rand::RngCore::next_u64(&mut b)).collect();
        for (k, w) in words.iter().enumerate() {
            let (lo, hi) = (*w as u32, (*w >> 32) as u32);
            assert_eq!(out[2 * k], (f64::from(lo) + 0.5) / 4_294_967_296.0);
            assert_eq!(out[2 * k + 1], (f64::from(hi) + 0.5) / 4_294_967_296.0);
        }
        assert!(out.iter().all(|&u| u > 0.0 && u < 1.0));
        let mut c = run_rng(5, 0);
        let mut split = vec![0.0; 100];
        fill_unit_f64_32(&mut c, &mut split[..64]);
        fill_unit_f64_32(&mut c, &mut split[64..]);
        assert_eq!(split, out);
    }

    /// `fill_u32` hands out exactly `fill`'s words and leaves the stream where `fill` does,
    /// from any position (odd word offsets and block boundaries included).
    #[test]
    fn word_fill_equals_bulk_fill() {
        let mut a = run_rng(9, 2);
        let mut b = a.clone();
        for len in [0usize, 1, 2, 3, 15, 30, 31, 63, 64, 65, 129, 300] {
            let _: u32 = a.random();
            let _: u32 = b.random();
            let mut ours = vec![0u32; len];
            let mut theirs = vec![0u32; len];
            fill_u32(&mut a, &mut ours);
            b.fill(&mut theirs[..]);
            assert_eq!(ours, theirs, "len {len}");
            assert_eq!(a.random::<u64>(), b.random::<u64>(), "len {len}");
        }
    }

    #[test]
    fn streams_differ_and_repeat() {
        let a: u64 = run_rng(7, 0).random();
        let b: u64 = run_rng(7, 1).random();
        assert_ne!(a, b);
        assert_eq!(a, run_rng(7, 0).random::<u64>());
    }

    #[test]
    fn bulk_uniform_draws_equal_single_draws() {
        // Odd lengths and a 32-bit draw in between shift the stream off word and block
        // boundaries; the bulk draws must still be the single draws, bit for bit.
        let mut a = run_rng(11, 3);
        let mut b = a.clone();
        for len in [0usize, 1, 7, 31, 32, 33, 64, 100, 257] {
            let _: u32 = a.random();
            let _: u32 = b.random();
            let mut bulk = vec![0.0; len];
            fill_unit_f64(&mut a, &mut bulk);
            let single: Vec<f64> = (0..len).map(|_| b.random::<f64>()).collect();
            assert_eq!(
                bulk.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                single.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                "len {len}"
            );
            assert!(bulk.iter().all(|v| (0.0..1.0).contains(v)));
        }
        assert_eq!(a.random::<u64>(), b.random::<u64>());
    }

    #[test]
    fn unit_conversion_is_exact() {
        let reference = |w: u64| (w >> 11) as f64 / (1u64 << 53) as f64;
        let mut words = vec![0, 1, 1 << 11, (1 << 11) - 1, 1 << 63, (1 << 63) - 1, u64::MAX, u64::MAX - (1 << 11)];
        let mut rng = run_rng(5, 0);
        words.extend((0..100_000).map(|_| rng.random::<u64>()));
        for w in words {
            assert_eq!(unit_f64(w).to_bits(), reference(w).to_bits(), "word {w:#x}");
        }
    }

    #[test]
    fn derived_seed_separates_labels() {
        assert_ne!(derive_seed(1, &["ab", "c"]), derive_seed(1, &["a", "bc"]));
        assert_ne!(derive_seed(1, &["demo"]), derive_seed(2, &["demo"]));
        assert_eq!(derive_seed(1, &["demo", "pso"]), derive_seed(1, &["demo", "pso"]));
    }
}
