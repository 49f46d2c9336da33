//! A material's uniform bytes: one of its pass's uniform blocks filled from the material's
//! values by member name, at the offsets the manifest gives (the WGSL spec's), so a renderer
//! writes no struct of its own for material data.

use super::{Library, RuntimeError};
use kiln_manifest::{MaterialManifest, Member};

impl Library {
    /// The bytes of the uniform block bound as `block` (its variable's name, `UnityPerMaterial`)
    /// in pass `pass` of the material's shader, `size` bytes long: a member named after a
    /// property holds the material's value (a number as the member's scalar type, a colour or
    /// vector component by component, `f32`/`i32`/`u32` scalars and vectors); a `NAME_ST` member
    /// of a texture property holds the texture's scale and offset, `(1, 1, 0, 0)`; everything
    /// else is zero.
    pub fn material_uniform(
        &self,
        material: &MaterialManifest,
        pass: usize,
        block: &str,
    ) -> Result<Vec<u8>, RuntimeError> {
        let manifest = self.pass(&material.shader, pass)?;
        let block =
            manifest.uniform_blocks.iter().find(|b| b.name == block).ok_or_else(|| RuntimeError::Layout {
                shader: material.shader.clone(),
                pass,
                message: format!("no uniform block `{block}` in the pass"),
            })?;
        let mut bytes = vec![0u8; block.size as usize];
        for member in &block.members {
            let value = match material.values.get(&member.name) {
                Some(value) => components(value),
                None => texture_transform(material, member).unwrap_or_default(),
            };
            write_member(&mut bytes, member, &value);
        }
        Ok(bytes)
    }
}

/// A number or a vector of numbers; nothing for a texture name.
fn components(value: &serde_json::Value) -> Vec<f64> {
    match value {
        serde_json::Value::Number(n) => n.as_f64().into_iter().collect(),
        serde_json::Value::Array(items) => items.iter().filter_map(serde_json::Value::as_f64).collect(),
        _ => Vec::new(),
    }
}

/// `(1, 1, 0, 0)` for `NAME_ST` when `NAME` is one of the material's textures (Unity's tiling
/// and offset, which kiln's materials do not set).
fn texture_transform(material: &MaterialManifest, member: &Member) -> Option<Vec<f64>> {
    let texture = member.name.strip_suffix("_ST")?;
    material.values.get(texture)?.as_str()?;
    Some(vec![1.0, 1.0, 0.0, 0.0])
}

/// Writes up to the member's component count of `value` as its scalar type; other types
/// (matrices, arrays, structs, `f16`) stay zero.
fn write_member(bytes: &mut [u8], member: &Member, value: &[f64]) {
    let (count, scalar) = match member.ty.strip_prefix("vec").and_then(|t| t.split_once('<')) {
        Some((n, scalar)) => (n.parse().unwrap_or(0), scalar.trim_end_matches('>')),
        None => (1, member.ty.as_str()),
    };
    for (i, &v) in value.iter().take(count).enumerate() {
        let word = match scalar {
            "f32" => (v as f32).to_le_bytes(),
            "i32" => (v as i32).to_le_bytes(),
            "u32" => (v as u32).to_le_bytes(),
            _ => return,
        };
        let at = member.offset as usize + 4 * i;
        if let Some(slot) = bytes.get_mut(at..at + 4) {
            slot.copy_from_slice(&word);
        }
    }
}
