//! The little-endian encoding of snapshots: numbers as their bits, so that
//! a restored value is the saved one to the last bit; every read names what
//! it reads, so that a snapshot that ends early says where.

use super::snapshot::SnapshotError;

/// Appends values to a snapshot.
#[derive(Default)]
pub(super) struct Writer(pub Vec<u8>);

impl Writer {
    pub fn u8(&mut self, v: u8) {
        self.0.push(v);
    }

    pub fn u32(&mut self, v: u32) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }

    pub fn u64(&mut self, v: u64) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }

    pub fn usize(&mut self, v: usize) {
        self.u64(v as u64);
    }

    /// An f64 as its bits (NaN payloads and −0 included).
    pub fn f64(&mut self, v: f64) {
        self.u64(v.to_bits());
    }

    pub fn option_f64(&mut self, v: Option<f64>) {
        self.u8(v.is_some() as u8);
        self.f64(v.unwrap_or(0.0));
    }

    pub fn bytes(&mut self, v: &[u8]) {
        self.usize(v.len());
        self.0.extend_from_slice(v);
    }

    pub fn str(&mut self, v: &str) {
        self.bytes(v.as_bytes());
    }

    pub fn f64s(&mut self, v: &[f64]) {
        self.usize(v.len());
        self.0.reserve(8 * v.len());
        for &x in v {
            self.f64(x);
        }
    }
}

/// Reads values back, failing with the name of what it was reading.
pub(super) struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    pub fn new(bytes: &'a [u8]) -> Self {
        Reader { bytes, at: 0 }
    }

    /// Bytes not read yet.
    pub fn remaining(&self) -> usize {
        self.bytes.len() - self.at
    }

    fn take(&mut self, n: usize, what: &'static str) -> Result<&'a [u8], SnapshotError> {
        if self.remaining() < n {
            return Err(SnapshotError::Truncated { what });
        }
        let out = &self.bytes[self.at..self.at + n];
        self.at += n;
        Ok(out)
    }

    fn array<const N: usize>(&mut self, what: &'static str) -> Result<[u8; N], SnapshotError> {
        let mut out = [0; N];
        out.copy_from_slice(self.take(N, what)?);
        Ok(out)
    }

    pub fn u8(&mut self, what: &'static str) -> Result<u8, SnapshotError> {
        Ok(self.take(1, what)?[0])
    }

    pub fn u32(&mut self, what: &'static str) -> Result<u32, SnapshotError> {
        self.array(what).map(u32::from_le_bytes)
    }

    pub fn u64(&mut self, what: &'static str) -> Result<u64, SnapshotError> {
        self.array(what).map(u64::from_le_bytes)
    }

    /// A count or an index: it must fit this machine's usize.
    pub fn usize(&mut self, what: &'static str) -> Result<usize, SnapshotError> {
        let v = self.u64(what)?;
        usize::try_from(v).map_err(|_| SnapshotError::invalid(what, format!("{v} is too large")))
    }

    pub fn f64(&mut self, what: &'static str) -> Result<f64, SnapshotError> {
        self.u64(what).map(f64::from_bits)
    }

    pub fn bool(&mut self, what: &'static str) -> Result<bool, SnapshotError> {
        match self.u8(what)? {
            0 => Ok(false),
            1 => Ok(true),
            v => Err(SnapshotError::invalid(
                what,
                format!("flag {v} is not 0 or 1"),
            )),
        }
    }

    pub fn option_f64(&mut self, what: &'static str) -> Result<Option<f64>, SnapshotError> {
        let some = self.bool(what)?;
        let v = self.f64(what)?;
        Ok(some.then_some(v))
    }

    /// A length, checked against the bytes left before anything is
    /// allocated (a corrupt length must not ask for memory it cannot have).
    fn len(&mut self, item: usize, what: &'static str) -> Result<usize, SnapshotError> {
        let n = self.usize(what)?;
        match n.checked_mul(item) {
            Some(size) if size <= self.remaining() => Ok(n),
            _ => Err(SnapshotError::Truncated { what }),
        }
    }

    pub fn bytes(&mut self, what: &'static str) -> Result<&'a [u8], SnapshotError> {
        let n = self.len(1, what)?;
        self.take(n, what)
    }

    pub fn string(&mut self, what: &'static str) -> Result<String, SnapshotError> {
        let bytes = self.bytes(what)?;
        String::from_utf8(bytes.to_vec())
            .map_err(|_| SnapshotError::invalid(what, "not UTF-8 text".to_string()))
    }

    pub fn f64s(&mut self, what: &'static str) -> Result<Vec<f64>, SnapshotError> {
        let n = self.len(8, what)?;
        let raw = self.take(8 * n, what)?;
        Ok(raw
            .chunks_exact(8)
            .map(|c| f64::from_bits(u64::from_le_bytes(c.try_into().unwrap_or_default())))
            .collect())
    }
}

/// A 64-bit checksum of `bytes`, word by word (FNV-1a's prime on
/// little-endian words, then a final mix): every step is a bijection of the
/// running state, so a snapshot differing in any one word never matches.
pub(super) fn checksum(bytes: &[u8]) -> u64 {
    const PRIME: u64 = 0x0000_0100_0000_01b3;
    let mut h: u64 = 0xcbf2_9ce4_8422_2325 ^ bytes.len() as u64;
    let mut words = bytes.chunks_exact(8);
    for w in &mut words {
        let word = u64::from_le_bytes(w.try_into().unwrap_or_default());
        h = (h ^ word).wrapping_mul(PRIME).rotate_left(29);
    }
    let mut tail = [0u8; 8];
    tail[..words.remainder().len()].copy_from_slice(words.remainder());
    h = (h ^ u64::from_le_bytes(tail)).wrapping_mul(PRIME);
    // splitmix64's finaliser: every input bit reaches every output bit.
    h ^= h >> 30;
    h = h.wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h ^= h >> 27;
    h = h.wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^ (h >> 31)
}
