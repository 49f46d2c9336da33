//! What the manifest says of a stage module's interface: vertex attributes and colour targets,
//! resources, and uniform and storage block layouts (filled in by the compiler's `reflect` stage from naga).

use serde::{Deserialize, Serialize};

/// A vertex attribute or a colour target.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Attribute {
    /// Its `@location`.
    pub location: u32,
    /// Its name in the WGSL struct or parameter.
    pub name: String,
    /// Its format, as WebGPU names vertex formats (`float32x3`).
    pub format: AttributeFormat,
}

closed_set! {
    /// A vertex input's or a colour output's format: a scalar or vector of a WGSL (or naga's
    /// 64-bit) type, as WebGPU names vertex formats; `unsupported` for a type none names.
    AttributeFormat {
        /// `float16`.
        Float16 = "float16",
        /// `float16x2`.
        Float16x2 = "float16x2",
        /// `float16x3`.
        Float16x3 = "float16x3",
        /// `float16x4`.
        Float16x4 = "float16x4",
        /// `float32`.
        Float32 = "float32",
        /// `float32x2`.
        Float32x2 = "float32x2",
        /// `float32x3`.
        Float32x3 = "float32x3",
        /// `float32x4`.
        Float32x4 = "float32x4",
        /// `float64`.
        Float64 = "float64",
        /// `float64x2`.
        Float64x2 = "float64x2",
        /// `float64x3`.
        Float64x3 = "float64x3",
        /// `float64x4`.
        Float64x4 = "float64x4",
        /// `sint32`.
        Sint32 = "sint32",
        /// `sint32x2`.
        Sint32x2 = "sint32x2",
        /// `sint32x3`.
        Sint32x3 = "sint32x3",
        /// `sint32x4`.
        Sint32x4 = "sint32x4",
        /// `sint64`.
        Sint64 = "sint64",
        /// `sint64x2`.
        Sint64x2 = "sint64x2",
        /// `sint64x3`.
        Sint64x3 = "sint64x3",
        /// `sint64x4`.
        Sint64x4 = "sint64x4",
        /// `uint32`.
        Uint32 = "uint32",
        /// `uint32x2`.
        Uint32x2 = "uint32x2",
        /// `uint32x3`.
        Uint32x3 = "uint32x3",
        /// `uint32x4`.
        Uint32x4 = "uint32x4",
        /// `uint64`.
        Uint64 = "uint64",
        /// `uint64x2`.
        Uint64x2 = "uint64x2",
        /// `uint64x3`.
        Uint64x3 = "uint64x3",
        /// `uint64x4`.
        Uint64x4 = "uint64x4",
        /// A type no format names.
        Unsupported = "unsupported",
    }
}

impl AttributeFormat {
    /// The format of a `count`-component vector of `kind` (`float`, `sint`, `uint`) scalars of
    /// `bits` bits.
    pub fn of(kind: &str, bits: u32, count: u32) -> AttributeFormat {
        let name = match count {
            1 => format!("{kind}{bits}"),
            _ => format!("{kind}{bits}x{count}"),
        };
        AttributeFormat::ALL
            .iter()
            .copied()
            .find(|f| f.name() == name)
            .unwrap_or(AttributeFormat::Unsupported)
    }
}

closed_set! {
    /// A pipeline stage (in the order `visibility` lists them).
    ShaderStage {
        /// A compute kernel.
        Compute = "compute",
        /// The fragment stage.
        Fragment = "fragment",
        /// The vertex stage.
        Vertex = "vertex",
    }
}

closed_set! {
    /// A texture's view dimension, as WGSL's texture types spell it (`texture_2d_array`).
    ViewDimension {
        /// `texture_1d`.
        D1 = "1d",
        /// `texture_2d`.
        D2 = "2d",
        /// `texture_2d_array`.
        D2Array = "2d_array",
        /// `texture_3d`.
        D3 = "3d",
        /// `texture_cube`.
        Cube = "cube",
        /// `texture_cube_array`.
        CubeArray = "cube_array",
    }
}

closed_set! {
    /// What a sampled texture returns.
    SampleType {
        /// `f32` texels (filterable unless multisampled).
        Float = "float",
        /// A depth texture (`texture_depth_*`).
        Depth = "depth",
        /// `i32` texels.
        Sint = "sint",
        /// `u32` texels.
        Uint = "uint",
    }
}

closed_set! {
    /// A storage texture's access mode, as WGSL writes it.
    StorageAccess {
        /// `read`.
        Read = "read",
        /// `write`.
        Write = "write",
        /// `read_write`.
        ReadWrite = "read_write",
        /// `atomic`: atomic operations on its texels.
        Atomic = "atomic",
    }
}

closed_set! {
    /// A storage texture's texel format, as WGSL writes it (`rgba8unorm`).
    TexelFormat {
        /// `r8unorm`.
        R8Unorm = "r8unorm",
        /// `r8snorm`.
        R8Snorm = "r8snorm",
        /// `r8uint`.
        R8Uint = "r8uint",
        /// `r8sint`.
        R8Sint = "r8sint",
        /// `r16uint`.
        R16Uint = "r16uint",
        /// `r16sint`.
        R16Sint = "r16sint",
        /// `r16float`.
        R16Float = "r16float",
        /// `rg8unorm`.
        Rg8Unorm = "rg8unorm",
        /// `rg8snorm`.
        Rg8Snorm = "rg8snorm",
        /// `rg8uint`.
        Rg8Uint = "rg8uint",
        /// `rg8sint`.
        Rg8Sint = "rg8sint",
        /// `r32uint`.
        R32Uint = "r32uint",
        /// `r32sint`.
        R32Sint = "r32sint",
        /// `r32float`.
        R32Float = "r32float",
        /// `rg16uint`.
        Rg16Uint = "rg16uint",
        /// `rg16sint`.
        Rg16Sint = "rg16sint",
        /// `rg16float`.
        Rg16Float = "rg16float",
        /// `rgba8unorm`.
        Rgba8Unorm = "rgba8unorm",
        /// `rgba8snorm`.
        Rgba8Snorm = "rgba8snorm",
        /// `rgba8uint`.
        Rgba8Uint = "rgba8uint",
        /// `rgba8sint`.
        Rgba8Sint = "rgba8sint",
        /// `bgra8unorm`.
        Bgra8Unorm = "bgra8unorm",
        /// `rgb10a2uint`.
        Rgb10a2Uint = "rgb10a2uint",
        /// `rgb10a2unorm`.
        Rgb10a2Unorm = "rgb10a2unorm",
        /// `rg11b10ufloat`.
        Rg11b10Ufloat = "rg11b10ufloat",
        /// `r64uint`.
        R64Uint = "r64uint",
        /// `rg32uint`.
        Rg32Uint = "rg32uint",
        /// `rg32sint`.
        Rg32Sint = "rg32sint",
        /// `rg32float`.
        Rg32Float = "rg32float",
        /// `rgba16uint`.
        Rgba16Uint = "rgba16uint",
        /// `rgba16sint`.
        Rgba16Sint = "rgba16sint",
        /// `rgba16float`.
        Rgba16Float = "rgba16float",
        /// `rgba32uint`.
        Rgba32Uint = "rgba32uint",
        /// `rgba32sint`.
        Rgba32Sint = "rgba32sint",
        /// `rgba32float`.
        Rgba32Float = "rgba32float",
        /// `r16unorm`.
        R16Unorm = "r16unorm",
        /// `r16snorm`.
        R16Snorm = "r16snorm",
        /// `rg16unorm`.
        Rg16Unorm = "rg16unorm",
        /// `rg16snorm`.
        Rg16Snorm = "rg16snorm",
        /// `rgba16unorm`.
        Rgba16Unorm = "rgba16unorm",
        /// `rgba16snorm`.
        Rgba16Snorm = "rgba16snorm",
    }
}

/// What a binding holds.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
// Each variant's fields are named in its comment.
#[allow(missing_docs)]
pub enum Resource {
    /// `var<uniform>`: its type and size in bytes.
    Uniform { type_name: String, size: u32 },
    /// `var<storage>`: its type, and whether it is `read`.
    Storage { type_name: String, read_only: bool },
    /// A sampled texture: its dimension, what it returns, whether it is multisampled.
    Texture { dimension: ViewDimension, sample_type: SampleType, multisampled: bool },
    /// A storage texture: its dimension, texel format and access.
    StorageTexture { dimension: ViewDimension, format: TexelFormat, access: StorageAccess },
    /// A sampler, comparison or not.
    Sampler { comparison: bool },
    /// Anything else, described.
    Other { description: String },
}

/// A uniform or storage buffer's contents, laid out by naga: a struct, or (for a storage buffer
/// holding a bare array) one member named after the buffer.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
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
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
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

closed_set! {
    /// The scalar type of an `override` constant (WGSL's, and the 64-bit ones naga allows).
    OverrideType {
        /// `bool`: 0 or 1.
        Bool = "bool",
        /// `i32`.
        I32 = "i32",
        /// `u32`.
        U32 = "u32",
        /// `i64` (naga's extension).
        I64 = "i64",
        /// `u64` (naga's extension).
        U64 = "u64",
        /// `f16` (`enable f16;`).
        F16 = "f16",
        /// `f32`.
        F32 = "f32",
        /// `f64` (naga's extension).
        F64 = "f64",
    }
}

/// A pipeline-overridable constant (WGSL `override`) a stage module uses, set by name (or by its
/// `@id`) when a pipeline is created. One named after a `dynamic_branch` keyword of its pass is
/// that keyword (kiln declares it).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct OverrideConstant {
    /// Its name in the WGSL.
    pub name: String,
    /// Its `@id`, if it has one: a pipeline then sets it by that number, written in decimal.
    pub id: Option<u16>,
    /// Its scalar type.
    #[serde(rename = "type")]
    pub ty: OverrideType,
    /// Its default as a number (`bool`: 0 or 1) when the WGSL gives it as a literal; `None` when
    /// it has none or computes it from other overrides.
    pub default: Option<f64>,
    /// Whether a pipeline must set it (it has no default).
    pub required: bool,
}

impl OverrideConstant {
    /// The key a pipeline sets it by: its `@id` in decimal, else its name (WebGPU's rule).
    pub fn key(&self) -> String {
        self.id.map_or_else(|| self.name.clone(), |id| id.to_string())
    }

    /// Whether `value` is one of its type's values: 0 or 1 for `bool`, a whole number in range
    /// for the integers, finite and in range for the floats.
    pub fn accepts(&self, value: f64) -> bool {
        let whole = value.fract() == 0.0;
        match self.ty {
            OverrideType::Bool => value == 0.0 || value == 1.0,
            OverrideType::I32 => whole && (f64::from(i32::MIN)..=f64::from(i32::MAX)).contains(&value),
            OverrideType::U32 => whole && (0.0..=f64::from(u32::MAX)).contains(&value),
            // As wgpu passes them: an f64, whole, that the 64-bit integer holds.
            OverrideType::I64 => whole && (-(2f64.powi(63))..2f64.powi(63)).contains(&value),
            OverrideType::U64 => whole && (0.0..2f64.powi(64)).contains(&value),
            OverrideType::F16 => value.is_finite() && value.abs() <= 65504.0,
            OverrideType::F32 => value.is_finite() && value.abs() <= f64::from(f32::MAX),
            OverrideType::F64 => value.is_finite(),
        }
    }
}

// Interfaces are deduplicated by hash; a default compares by its bits.
impl Eq for OverrideConstant {}

impl std::hash::Hash for OverrideConstant {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        (&self.name, self.id, &self.ty, self.default.map(f64::to_bits), self.required).hash(state);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_set_reads_its_names_and_refuses_any_other() {
        let read = |json: &str| serde_json::from_str::<Resource>(json);
        let storage = r#"{"kind": "storage_texture", "dimension": "2d_array", "format": "rgba8unorm", "access": "read"}"#;
        assert_eq!(
            read(storage).expect("WGSL's names"),
            Resource::StorageTexture {
                dimension: ViewDimension::D2Array,
                format: TexelFormat::Rgba8Unorm,
                access: StorageAccess::Read
            }
        );
        // What schema 7 wrote for a `read` texture: refused, naming the set.
        let old = storage.replace(r#""read""#, r#""storageaccess(load)""#);
        let error = read(&old).expect_err("not an access mode").to_string();
        assert!(error.contains("storageaccess(load)") && error.contains("read_write"), "{error}");
        assert!(read(&storage.replace("2d_array", "4d")).is_err());
        // Every value writes the name it reads back from.
        for &format in TexelFormat::ALL {
            let json = serde_json::to_string(&format).expect("writes");
            assert_eq!(serde_json::from_str::<TexelFormat>(&json).expect("reads"), format, "{json}");
        }
    }

    #[test]
    fn an_attribute_s_format_is_webgpu_s_name_or_unsupported() {
        assert_eq!(AttributeFormat::of("float", 32, 3), AttributeFormat::Float32x3);
        assert_eq!(AttributeFormat::of("uint", 32, 1), AttributeFormat::Uint32);
        assert_eq!(AttributeFormat::of("sint", 8, 2), AttributeFormat::Unsupported);
        for &format in AttributeFormat::ALL {
            let json = serde_json::to_string(&format).expect("writes");
            assert_eq!(serde_json::from_str::<AttributeFormat>(&json).expect("reads"), format, "{json}");
        }
        assert!(serde_json::from_str::<AttributeFormat>(r#""float32x5""#).is_err());
    }

    #[test]
    fn an_override_s_type_is_a_scalar_and_bounds_its_values() {
        let constant = |ty: &str| {
            serde_json::from_str::<OverrideConstant>(&format!(
                r#"{{"name": "n", "id": null, "type": "{ty}", "default": null, "required": true}}"#
            ))
        };
        assert!(constant("vec2<f32>").is_err(), "not a scalar");
        for &ty in OverrideType::ALL {
            let read = constant(ty.name()).expect("a scalar type");
            assert_eq!(read.ty, ty);
            assert!(read.accepts(1.0) && !read.accepts(f64::NAN), "{ty}");
        }
        let accepts = |ty: &str, value: f64| constant(ty).expect("reads").accepts(value);
        assert!(!accepts("bool", 2.0) && !accepts("u32", -1.0) && !accepts("i32", 0.5));
        assert!(accepts("u64", 2f64.powi(40)) && !accepts("u32", 2f64.powi(40)));
        assert!(accepts("f32", 1e30) && !accepts("f16", 1e30) && accepts("f64", 1e300));
    }
}
