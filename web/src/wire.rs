//! Jobs and results as bytes between the page and its Web Workers:
//! MessagePack with named fields (self-describing, so optional fields left
//! out by the model's serde attributes read back; binary, so floats keep
//! every bit, infinities and NaN included).

/// `value` as bytes.
pub fn encode<T: serde::Serialize>(value: &T) -> Result<Vec<u8>, String> {
    rmp_serde::to_vec_named(value).map_err(|e| e.to_string())
}

/// A value from bytes made by [`encode`].
pub fn decode<T: serde::de::DeserializeOwned>(bytes: &[u8]) -> Result<T, String> {
    rmp_serde::from_slice(bytes).map_err(|e| e.to_string())
}
