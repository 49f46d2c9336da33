//! A material's bind group: the pass's per-material group (group 1 by the update-frequency rule)
//! with its uniform blocks filled from the material's values, and its textures and samplers by
//! property name from the renderer, so a renderer writes no binding code per material.

use super::{Library, PassId, Runtime, RuntimeError};
use kiln_manifest::MaterialManifest;
use kiln_manifest::Resource;
use wgpu::util::DeviceExt;

pub use kiln_manifest::MATERIAL_GROUP;

/// The renderer's textures and samplers, as materials name them.
pub trait MaterialTextures {
    /// The view of the texture a material's texture property holds: `property` is its name
    /// (`_BaseMap`), `texture` the material's value for it (a texture name such as `"white"`).
    fn texture(&self, property: &str, texture: &str) -> Option<&wgpu::TextureView>;
    /// The sampler a pass binds for a texture property (`sampler_BaseMap` samples `_BaseMap`).
    fn sampler(&self, property: &str) -> Option<&wgpu::Sampler>;
}

/// No textures: for a material whose pass samples none.
impl MaterialTextures for () {
    fn texture(&self, _property: &str, _texture: &str) -> Option<&wgpu::TextureView> {
        None
    }
    fn sampler(&self, _property: &str) -> Option<&wgpu::Sampler> {
        None
    }
}

/// A material's bind group for a pass, with the uniform buffers it owns.
#[derive(Debug)]
pub struct MaterialBindGroup {
    /// The group it is bound at ([`MATERIAL_GROUP`]).
    pub group: u32,
    /// The bind group.
    pub bind_group: wgpu::BindGroup,
    /// The pass it was made for.
    pass: usize,
    /// Each uniform block's buffer, by the block's name.
    buffers: Vec<(String, wgpu::Buffer)>,
}

impl MaterialBindGroup {
    /// The buffer of a uniform block of the group, by its name (`UnityPerMaterial`).
    pub fn buffer(&self, block: &str) -> Option<&wgpu::Buffer> {
        self.buffers.iter().find(|(name, _)| name == block).map(|(_, buffer)| buffer)
    }

    /// Writes a material's values (the same material, changed) into the group's uniform buffers.
    pub fn update(
        &self,
        library: &Library,
        queue: &wgpu::Queue,
        material: &MaterialManifest,
    ) -> Result<(), RuntimeError> {
        for (block, buffer) in &self.buffers {
            queue.write_buffer(buffer, 0, &library.material_uniform(material, self.pass, block)?);
        }
        Ok(())
    }
}

impl Runtime {
    /// The material's bind group for a pass of its shader: each uniform block filled by
    /// [`Library::material_uniform`], each texture and sampler from `textures` by property name.
    /// A resource the renderer does not provide, or a pass of another shader, is an error naming
    /// it.
    pub fn material_bind_group(
        &self,
        material: &MaterialManifest,
        pass: PassId,
        textures: &dyn MaterialTextures,
    ) -> Result<MaterialBindGroup, RuntimeError> {
        let shader = self.library.shader_name(pass);
        let manifest = self.library.pass_of(pass)?;
        let layout = self.pass_facts(pass)?.layout;
        let pass = manifest.index;
        let layout_error =
            |message: String| RuntimeError::Layout { shader: shader.to_string(), pass, message };
        if material.shader != shader {
            return Err(layout_error(format!("`{}` is a material of `{}`", material.name, material.shader)));
        }
        let entries =
            manifest.layout.iter().find(|g| g.group == MATERIAL_GROUP).map_or(&[][..], |g| &g.entries[..]);
        let group_layout = layout.groups.get(MATERIAL_GROUP as usize).ok_or_else(|| {
            layout_error(format!("the pass has no bind group {MATERIAL_GROUP} for a material"))
        })?;
        let mut buffers = Vec::new();
        for entry in entries.iter().filter(|e| matches!(e.resource, Resource::Uniform { .. })) {
            let bytes = self.library.material_uniform(material, pass, &entry.name)?;
            let buffer = self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(&entry.name),
                contents: &bytes,
                usage: wgpu::BufferUsages::UNIFORM
                    | wgpu::BufferUsages::COPY_DST
                    | wgpu::BufferUsages::COPY_SRC,
            });
            buffers.push((entry.name.clone(), buffer));
        }
        let mut bound = Vec::with_capacity(entries.len());
        for entry in entries {
            let resource = match &entry.resource {
                Resource::Uniform { .. } => {
                    let buffer = buffers.iter().find(|(name, _)| *name == entry.name).map(|(_, b)| b);
                    buffer.map(wgpu::Buffer::as_entire_binding)
                }
                Resource::Texture { .. } => {
                    let value = material.values.get(&entry.name).and_then(|v| v.as_str()).unwrap_or_default();
                    let view = textures.texture(&entry.name, value);
                    Some(wgpu::BindingResource::TextureView(view.ok_or_else(|| {
                        layout_error(format!("no texture for `{}` (`{value}`)", entry.name))
                    })?))
                }
                Resource::Sampler { .. } => {
                    let property = entry.name.strip_prefix("sampler").unwrap_or(&entry.name);
                    let sampler = textures.sampler(property);
                    Some(wgpu::BindingResource::Sampler(
                        sampler.ok_or_else(|| layout_error(format!("no sampler for `{}`", entry.name)))?,
                    ))
                }
                _ => None,
            };
            let resource = resource.ok_or_else(|| {
                layout_error(format!(
                    "a material cannot bind `{}` (not a uniform, texture or sampler)",
                    entry.name
                ))
            })?;
            bound.push(wgpu::BindGroupEntry { binding: entry.binding, resource });
        }
        let bind_group = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(&material.name),
            layout: group_layout,
            entries: &bound,
        });
        Ok(MaterialBindGroup { group: MATERIAL_GROUP, bind_group, pass, buffers })
    }
}

impl Runtime {
    /// A bind group of buffers the renderer owns (group 0 per frame, 2 per object), each bound by
    /// its name in the pass's layout (`("UnityPerFrame", &buffer)`), so the renderer needs no
    /// binding numbers. A binding of the group without a buffer, or a name the group does not
    /// have, is an error naming it.
    pub fn buffer_bind_group(
        &self,
        pass: PassId,
        group: u32,
        buffers: &[(&str, &wgpu::Buffer)],
    ) -> Result<wgpu::BindGroup, RuntimeError> {
        let shader = self.library.shader_name(pass);
        let manifest = self.library.pass_of(pass)?;
        let layout = self.pass_facts(pass)?.layout;
        let pass = manifest.index;
        let layout_error =
            |message: String| RuntimeError::Layout { shader: shader.to_string(), pass, message };
        let entries = manifest.layout.iter().find(|g| g.group == group).map_or(&[][..], |g| &g.entries[..]);
        let group_layout = layout
            .groups
            .get(group as usize)
            .filter(|_| !entries.is_empty())
            .ok_or_else(|| layout_error(format!("the pass has no bind group {group}")))?;
        if let Some((name, _)) = buffers.iter().find(|(name, _)| !entries.iter().any(|e| e.name == *name)) {
            let names: Vec<&str> = entries.iter().map(|e| e.name.as_str()).collect();
            let hint = kiln_manifest::closest(name, names.iter().copied())
                .map(|s| format!(" (did you mean `{s}`?)"))
                .unwrap_or_default();
            return Err(layout_error(format!("group {group} has no binding `{name}`{hint}")));
        }
        let bound = entries
            .iter()
            .map(|entry| {
                let buffer = buffers.iter().find(|(name, _)| *name == entry.name).map(|(_, b)| *b);
                let buffer = buffer.ok_or_else(|| {
                    layout_error(format!("no buffer for `{}` in group {group}", entry.name))
                })?;
                Ok(wgpu::BindGroupEntry { binding: entry.binding, resource: buffer.as_entire_binding() })
            })
            .collect::<Result<Vec<_>, RuntimeError>>()?;
        Ok(self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(&format!("{shader} pass {pass} group {group}")),
            layout: group_layout,
            entries: &bound,
        }))
    }
}
