//! What the manifest says of a stage module's interface: vertex attributes and colour targets,
//! resources, and uniform and storage block layouts (filled in by `crate::reflect` from naga).

use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Attribute {
    pub location: u32,
    pub name: String,
    /// WebGPU vertex or texel format, such as `float32x3`.
    pub format: String,
}

#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Resource {
    Uniform { type_name: String, size: u32 },
    Storage { type_name: String, read_only: bool },
    Texture { dimension: String, sample_type: String, multisampled: bool },
    StorageTexture { dimension: String, format: String, access: String },
    Sampler { comparison: bool },
    Other { description: String },
}

/// A uniform or storage buffer's contents, laid out by naga: a struct, or (for a storage buffer
/// holding a bare array) one member named after the buffer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct UniformBlock {
    /// The global variable's name (`_CustomLight`).
    pub name: String,
    pub type_name: String,
    /// For a storage buffer ending in a runtime-sized array: the size without that array.
    pub size: u32,
    pub alignment: u32,
    /// A storage buffer (`var<storage>`) rather than a uniform one.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub storage: bool,
    pub members: Vec<Member>,
}

/// A struct member, with its offset in the struct that holds it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Member {
    pub name: String,
    #[serde(rename = "type")]
    pub ty: String,
    pub offset: u32,
    pub size: u32,
    pub alignment: u32,
    /// For arrays: the element stride and the length (`None` for a runtime-sized array).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub array_stride: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub array_length: Option<u32>,
    /// When the member is a struct, or an array of structs: that struct's members, with offsets
    /// relative to the struct (to an array element for arrays).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub members: Vec<Member>,
}
