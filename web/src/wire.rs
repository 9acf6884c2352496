//! Jobs and results as bytes between the page and its Web Workers: RON,
//! the format of presets and sessions, whose serializers the module has
//! already (a second format would add its own copy of every type's
//! serializer, a few hundred kilobytes). Self-describing, so optional fields
//! left out by the model's serde attributes read back; floats are written in
//! their shortest form that reads back to the same bits, infinities and NaN
//! included.

/// `value` as bytes.
pub fn encode<T: serde::Serialize>(value: &T) -> Result<Vec<u8>, String> {
    ron::to_string(value).map(String::into_bytes).map_err(|e| e.to_string())
}

/// A value from bytes made by [`encode`].
pub fn decode<T: serde::de::DeserializeOwned>(bytes: &[u8]) -> Result<T, String> {
    ron::de::from_bytes(bytes).map_err(|e| e.to_string())
}
