//! A fast hash for the symbol table's names: short identifiers looked up once or more per token
//! read (loops run their bodies' tokens again), where SipHash's protection against chosen keys
//! buys nothing (a scene cannot make the parser slower than its own loops do).

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// The multiply-rotate word hash of rustc's `FxHasher`, eight bytes at a time.
#[derive(Clone, Copy, Default)]
pub struct NameHasher(u64);

const SEED: u64 = 0x51_7c_c1_b7_27_22_0a_95;

impl NameHasher {
    fn add(&mut self, word: u64) {
        self.0 = (self.0.rotate_left(5) ^ word).wrapping_mul(SEED);
    }
}

impl Hasher for NameHasher {
    fn write(&mut self, bytes: &[u8]) {
        let mut chunks = bytes.chunks_exact(8);
        for c in &mut chunks {
            let mut w = [0u8; 8];
            w.copy_from_slice(c);
            self.add(u64::from_le_bytes(w));
        }
        let rest = chunks.remainder();
        if !rest.is_empty() {
            let mut w = [0u8; 8];
            w[..rest.len()].copy_from_slice(rest);
            self.add(u64::from_le_bytes(w));
        }
    }

    fn write_u8(&mut self, b: u8) {
        self.add(u64::from(b));
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

/// A map keyed by names, hashed with `NameHasher`.
pub type NameMap<K, V> = HashMap<K, V, BuildHasherDefault<NameHasher>>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_that_differ_hash_apart_and_maps_work() {
        let mut m: NameMap<&str, u32> = NameMap::default();
        for (i, w) in ["a", "b", "Colors_Inc_Temp", "Colors_Inc_Tem", "ab", "ba"].iter().enumerate() {
            m.insert(w, i as u32);
        }
        assert_eq!(m.get("Colors_Inc_Temp"), Some(&2));
        assert_eq!(m.get("ba"), Some(&5));
        assert_eq!(m.get("c"), None);
    }
}
