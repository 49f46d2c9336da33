//! What the manifest says of a stage module's interface: vertex attributes and colour targets,
//! resources, and uniform and storage block layouts (filled in by `crate::reflect` from naga).

use serde::{Deserialize, Serialize};

/// A vertex attribute or a colour target.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Attribute {
    /// Its `@location`.
    pub location: u32,
    /// Its name in the WGSL struct or parameter.
    pub name: String,
    /// WebGPU vertex or texel format, such as `float32x3`.
    pub format: String,
}

/// What a binding holds.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
// Each variant's fields are named in its comment.
#[allow(missing_docs)]
pub enum Resource {
    /// `var<uniform>`: its type and size in bytes.
    Uniform { type_name: String, size: u32 },
    /// `var<storage>`: its type, and whether it is `read`.
    Storage { type_name: String, read_only: bool },
    /// A sampled texture: `2d`, `cube`, ...; `float`, `depth`, `sint`, `uint`; multisampled.
    Texture { dimension: String, sample_type: String, multisampled: bool },
    /// A storage texture: its dimension, texel format and access.
    StorageTexture { dimension: String, format: String, access: String },
    /// A sampler, comparison or not.
    Sampler { comparison: bool },
    /// Anything else, described.
    Other { description: String },
}

/// A uniform or storage buffer's contents, laid out by naga: a struct, or (for a storage buffer
/// holding a bare array) one member named after the buffer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct UniformBlock {
    /// The global variable's name (`_CustomLight`).
    pub name: String,
    /// Its WGSL type's name.
    pub type_name: String,
    /// For a storage buffer ending in a runtime-sized array: the size without that array.
    pub size: u32,
    /// Its alignment, by the WGSL spec.
    pub alignment: u32,
    /// A storage buffer (`var<storage>`) rather than a uniform one.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub storage: bool,
    /// Its members, in order.
    pub members: Vec<Member>,
}

/// A struct member, with its offset in the struct that holds it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Member {
    /// Its name.
    pub name: String,
    /// Its WGSL type.
    #[serde(rename = "type")]
    pub ty: String,
    /// Byte offset in the struct that holds it.
    pub offset: u32,
    /// Size in bytes.
    pub size: u32,
    /// Alignment, by the WGSL spec.
    pub alignment: u32,
    /// For arrays: the element stride and the length (`None` for a runtime-sized array).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub array_stride: Option<u32>,
    /// The array's length.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub array_length: Option<u32>,
    /// When the member is a struct, or an array of structs: that struct's members, with offsets
    /// relative to the struct (to an array element for arrays).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub members: Vec<Member>,
}
