//! A pass's ShaderLab render state (`Blend [_SrcBlend] [_DstBlend]`, `ZWrite [_ZWrite]`, ...)
//! resolved with a material's property values into wgpu's pipeline state.
//!
//! The manifest holds each command parsed (and as written, for messages). `[_Property]` values
//! are numbers in Unity's enums (`UnityEngine.Rendering.BlendMode` and its siblings).

use kiln_manifest::unity_enum_name;
use kiln_manifest::{
    BlendFactor, BlendOperation, CompareFunction, CullMode, PassManifest, StateCommand, StencilField,
    StencilOperation, StencilSetting, StencilValue, Value,
};

/// Colour targets wgpu allows a pipeline.
pub const MAX_TARGETS: usize = 8;

/// One colour target's blending and write mask.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct TargetState {
    /// Blending, `None` when off.
    pub blend: Option<wgpu::BlendState>,
    /// The channels written.
    pub write_mask: wgpu::ColorWrites,
}

/// Everything in a pipeline that the pass's render state and a material decide.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderState {
    /// Each colour target's blending and mask.
    pub targets: [TargetState; MAX_TARGETS],
    /// Whether depth is written.
    pub depth_write: bool,
    /// `None` is `ZTest Disabled`: no depth test, and no depth write either (as in Unity).
    pub depth_compare: Option<wgpu::CompareFunction>,
    /// The faces culled.
    pub cull_mode: Option<wgpu::Face>,
    /// The depth bias.
    pub depth_bias: wgpu::DepthBiasState,
    /// The stencil test and operations.
    pub stencil: wgpu::StencilState,
    /// `Stencil { Ref n }`: wgpu sets it on the render pass (`set_stencil_reference`).
    pub stencil_reference: u32,
    /// Whether alpha drives coverage.
    pub alpha_to_coverage: bool,
    /// `ZClip Off`: needs `wgpu::Features::DEPTH_CLIP_CONTROL`.
    pub unclipped_depth: bool,
    /// `Conservative True`: needs `wgpu::Features::CONSERVATIVE_RASTERIZATION`.
    pub conservative: bool,
}

impl Eq for RenderState {}

impl std::hash::Hash for RenderState {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.targets.hash(state);
        (self.depth_write, self.depth_compare, self.cull_mode).hash(state);
        // Bias floats by their bits: two states are one pipeline only when identical.
        let bias = &self.depth_bias;
        (bias.constant, bias.slope_scale.to_bits(), bias.clamp.to_bits()).hash(state);
        (&self.stencil, self.stencil_reference).hash(state);
        (self.alpha_to_coverage, self.unclipped_depth, self.conservative).hash(state);
    }
}

impl Default for RenderState {
    /// ShaderLab's defaults: no blending, all channels, `ZWrite On`, `ZTest LEqual`, `Cull Back`.
    fn default() -> RenderState {
        RenderState {
            targets: [TargetState { blend: None, write_mask: wgpu::ColorWrites::ALL }; MAX_TARGETS],
            depth_write: true,
            depth_compare: Some(wgpu::CompareFunction::LessEqual),
            cull_mode: Some(wgpu::Face::Back),
            depth_bias: wgpu::DepthBiasState::default(),
            stencil: wgpu::StencilState::default(),
            stencil_reference: 0,
            alpha_to_coverage: false,
            unclipped_depth: false,
            conservative: false,
        }
    }
}

impl RenderState {
    /// The depth-stencil state for a depth attachment of this format.
    pub fn depth_stencil(&self, format: wgpu::TextureFormat) -> wgpu::DepthStencilState {
        wgpu::DepthStencilState {
            format,
            depth_write_enabled: Some(self.depth_write && self.depth_compare.is_some()),
            depth_compare: Some(self.depth_compare.unwrap_or(wgpu::CompareFunction::Always)),
            stencil: self.stencil.clone(),
            bias: self.depth_bias,
        }
    }

    /// The primitive state (culling, conservative rasterisation).
    pub fn primitive(&self) -> wgpu::PrimitiveState {
        wgpu::PrimitiveState {
            cull_mode: self.cull_mode,
            unclipped_depth: self.unclipped_depth,
            conservative: self.conservative,
            ..wgpu::PrimitiveState::default()
        }
    }
}

/// Render state wgpu cannot express, or a property value that names nothing.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
// Variant fields are named in each variant's message.
#[allow(missing_docs)]
#[non_exhaustive]
pub enum StateError {
    /// A command wgpu cannot express.
    #[error("`{command}`: wgpu has no {what}")]
    Unsupported { command: String, what: String },
    /// A `[_Property]` value that is not one of its enum's numbers.
    #[error("`{command}`: property `{property}` is {value}, which is not a {kind}")]
    BadValue { command: String, property: String, value: String, kind: &'static str },
}

/// Resolves a pass's render state with a material's values (`None` for a property the material
/// does not have: the command's default in the manifest is used, then ShaderLab's).
pub fn resolve(pass: &PassManifest, value: &dyn Fn(&str) -> Option<f64>) -> Result<RenderState, StateError> {
    PassState::new(pass).resolve(value)
}

/// A pass's render state commands (with their text, for errors) and each property's default,
/// ready to resolve with any material's values.
#[derive(Debug, Clone)]
pub struct PassState {
    commands: Vec<(String, StateCommand)>,
    defaults: Vec<(String, f64)>,
}

impl PassState {
    /// The state the pass's commands give with the shader's default values.
    pub fn new(pass: &PassManifest) -> PassState {
        let defaults = pass
            .render_state
            .iter()
            .flat_map(|c| &c.properties)
            .filter_map(|p| Some((p.name.clone(), p.default.as_f64()?)))
            .collect();
        let commands = pass.render_state.iter().map(|c| (c.command.clone(), c.state.clone())).collect();
        PassState { commands, defaults }
    }

    /// The state with a material's values (`None` for a property the material does not have:
    /// the command's default in the manifest is used, then 0).
    pub fn resolve(&self, value: &dyn Fn(&str) -> Option<f64>) -> Result<RenderState, StateError> {
        let mut state = RenderState::default();
        let default_of = |name: &str| self.defaults.iter().find(|(n, _)| n == name).map(|(_, v)| *v);
        let number = |property: &str| value(property).or_else(|| default_of(property)).unwrap_or(0.0);
        for (text, command) in &self.commands {
            let mut r = Resolver { command: text, number: &number };
            r.apply(command, &mut state)?;
        }
        Ok(state)
    }
}

struct Resolver<'a> {
    command: &'a str,
    number: &'a dyn Fn(&str) -> f64,
}

impl Resolver<'_> {
    fn unsupported(&self, what: impl Into<String>) -> StateError {
        StateError::Unsupported { command: self.command.to_string(), what: what.into() }
    }

    /// A `[_Property]` as one of Unity's enums, read back as the ShaderLab word.
    fn word<T>(
        &self,
        value: &Value<T>,
        unity_enum: &str,
        kind: &'static str,
        parse: fn(&str) -> Option<T>,
    ) -> Result<T, StateError>
    where
        T: Copy,
    {
        match value {
            Value::Literal(v) => Ok(*v),
            Value::Property(property) => {
                let n = (self.number)(property);
                let word = unity_enum_name(unity_enum, n).map(|name| match name {
                    // Unity's enum spells these out; ShaderLab abbreviates.
                    "LessEqual" => "LEqual",
                    "GreaterEqual" => "GEqual",
                    "Subtract" => "Sub",
                    "ReverseSubtract" => "RevSub",
                    "IncrementSaturate" => "IncrSat",
                    "DecrementSaturate" => "DecrSat",
                    "IncrementWrap" => "IncrWrap",
                    "DecrementWrap" => "DecrWrap",
                    other => other,
                });
                word.and_then(parse).ok_or_else(|| StateError::BadValue {
                    command: self.command.to_string(),
                    property: property.clone(),
                    value: n.to_string(),
                    kind,
                })
            }
        }
    }

    fn flag(&self, value: &Value<bool>) -> bool {
        match value {
            Value::Literal(on) => *on,
            Value::Property(property) => (self.number)(property) != 0.0,
        }
    }

    fn float(&self, value: &Value<f64>) -> f64 {
        match value {
            Value::Literal(v) => *v,
            Value::Property(property) => (self.number)(property),
        }
    }

    fn factor(&self, value: &Value<BlendFactor>) -> Result<wgpu::BlendFactor, StateError> {
        use wgpu::BlendFactor as W;
        let factor =
            self.word(value, "UnityEngine.Rendering.BlendMode", "blend factor", BlendFactor::from_word)?;
        Ok(match factor {
            BlendFactor::One => W::One,
            BlendFactor::Zero => W::Zero,
            BlendFactor::SrcColor => W::Src,
            BlendFactor::SrcAlpha => W::SrcAlpha,
            BlendFactor::SrcAlphaSaturate => W::SrcAlphaSaturated,
            BlendFactor::DstColor => W::Dst,
            BlendFactor::DstAlpha => W::DstAlpha,
            BlendFactor::OneMinusSrcColor => W::OneMinusSrc,
            BlendFactor::OneMinusSrcAlpha => W::OneMinusSrcAlpha,
            BlendFactor::OneMinusDstColor => W::OneMinusDst,
            BlendFactor::OneMinusDstAlpha => W::OneMinusDstAlpha,
        })
    }

    fn operation(&self, value: &Value<BlendOperation>) -> Result<wgpu::BlendOperation, StateError> {
        let op =
            self.word(value, "UnityEngine.Rendering.BlendOp", "blend operation", BlendOperation::from_word)?;
        Ok(match op {
            BlendOperation::Add => wgpu::BlendOperation::Add,
            BlendOperation::Sub => wgpu::BlendOperation::Subtract,
            BlendOperation::RevSub => wgpu::BlendOperation::ReverseSubtract,
            BlendOperation::Min => wgpu::BlendOperation::Min,
            BlendOperation::Max => wgpu::BlendOperation::Max,
            other => {
                return Err(self.unsupported(format!(
                    "blend operation `{}` (logical and advanced blend operations)",
                    other.name()
                )));
            }
        })
    }

    fn compare(&self, value: &Value<CompareFunction>) -> Result<Option<wgpu::CompareFunction>, StateError> {
        use wgpu::CompareFunction as W;
        let function = self.word(
            value,
            "UnityEngine.Rendering.CompareFunction",
            "compare function",
            CompareFunction::from_word,
        )?;
        Ok(Some(match function {
            CompareFunction::Never => W::Never,
            CompareFunction::Less => W::Less,
            CompareFunction::Equal => W::Equal,
            CompareFunction::LEqual => W::LessEqual,
            CompareFunction::Greater => W::Greater,
            CompareFunction::NotEqual => W::NotEqual,
            CompareFunction::GEqual => W::GreaterEqual,
            CompareFunction::Always => W::Always,
            CompareFunction::Disabled => return Ok(None),
        }))
    }

    fn stencil_operation(
        &self,
        value: &Value<StencilOperation>,
    ) -> Result<wgpu::StencilOperation, StateError> {
        use wgpu::StencilOperation as W;
        let op = self.word(
            value,
            "UnityEngine.Rendering.StencilOp",
            "stencil operation",
            StencilOperation::from_word,
        )?;
        Ok(match op {
            StencilOperation::Keep => W::Keep,
            StencilOperation::Zero => W::Zero,
            StencilOperation::Replace => W::Replace,
            StencilOperation::IncrSat => W::IncrementClamp,
            StencilOperation::DecrSat => W::DecrementClamp,
            StencilOperation::Invert => W::Invert,
            StencilOperation::IncrWrap => W::IncrementWrap,
            StencilOperation::DecrWrap => W::DecrementWrap,
        })
    }

    /// The targets a command applies to: one, or all.
    fn targets<'s>(
        &self,
        state: &'s mut RenderState,
        target: Option<u32>,
    ) -> Result<&'s mut [TargetState], StateError> {
        match target {
            None => Ok(&mut state.targets[..]),
            Some(t) if (t as usize) < MAX_TARGETS => Ok(&mut state.targets[t as usize..=t as usize]),
            Some(t) => Err(self.unsupported(format!("colour target {t} (it allows {MAX_TARGETS})"))),
        }
    }

    fn apply(&mut self, command: &StateCommand, state: &mut RenderState) -> Result<(), StateError> {
        match command {
            StateCommand::Blend { target, factors } => {
                let blend = match factors {
                    None => None,
                    Some(f) => {
                        let (src, dst) = (self.factor(&f.src)?, self.factor(&f.dst)?);
                        let (src_alpha, dst_alpha) = match &f.alpha {
                            Some([a, b]) => (self.factor(a)?, self.factor(b)?),
                            None => (src, dst),
                        };
                        let component = |src_factor, dst_factor| wgpu::BlendComponent {
                            src_factor,
                            dst_factor,
                            operation: wgpu::BlendOperation::Add,
                        };
                        Some((component(src, dst), component(src_alpha, dst_alpha)))
                    }
                };
                for t in self.targets(state, *target)? {
                    // BlendOp may have come first: keep its operations.
                    let ops = t.blend.map(|b| (b.color.operation, b.alpha.operation));
                    t.blend = blend.map(|(mut color, mut alpha)| {
                        if let Some((c, a)) = ops {
                            (color.operation, alpha.operation) = (c, a);
                        }
                        wgpu::BlendState { color, alpha }
                    });
                }
            }
            StateCommand::BlendOp { target, color, alpha } => {
                let color_op = self.operation(color)?;
                let alpha_op = match alpha {
                    Some(a) => self.operation(a)?,
                    None => color_op,
                };
                for t in self.targets(state, *target)? {
                    let mut blend = t.blend.unwrap_or(wgpu::BlendState::REPLACE);
                    blend.color.operation = color_op;
                    blend.alpha.operation = alpha_op;
                    // Min and Max ignore the factors; wgpu wants them One.
                    for c in [&mut blend.color, &mut blend.alpha] {
                        if matches!(c.operation, wgpu::BlendOperation::Min | wgpu::BlendOperation::Max) {
                            (c.src_factor, c.dst_factor) = (wgpu::BlendFactor::One, wgpu::BlendFactor::One);
                        }
                    }
                    t.blend = Some(blend);
                }
            }
            StateCommand::ZWrite { on } => state.depth_write = self.flag(on),
            StateCommand::ZTest { function } => state.depth_compare = self.compare(function)?,
            StateCommand::ZClip { on } => state.unclipped_depth = !self.flag(on),
            StateCommand::Cull { mode } => {
                let mode =
                    self.word(mode, "UnityEngine.Rendering.CullMode", "cull mode", CullMode::from_word)?;
                state.cull_mode = match mode {
                    CullMode::Off => None,
                    CullMode::Front => Some(wgpu::Face::Front),
                    CullMode::Back => Some(wgpu::Face::Back),
                };
            }
            StateCommand::ColorMask { mask, target } => {
                let write_mask = match mask {
                    Value::Literal(m) => {
                        let mut w = wgpu::ColorWrites::empty();
                        for (on, bit) in [
                            (m.r, wgpu::ColorWrites::RED),
                            (m.g, wgpu::ColorWrites::GREEN),
                            (m.b, wgpu::ColorWrites::BLUE),
                            (m.a, wgpu::ColorWrites::ALPHA),
                        ] {
                            if on {
                                w |= bit;
                            }
                        }
                        w
                    }
                    // Unity's ColorWriteMask: Alpha 1, Blue 2, Green 4, Red 8.
                    Value::Property(property) => {
                        let bits = (self.number)(property).round().clamp(0.0, 15.0) as u32;
                        let mut w = wgpu::ColorWrites::empty();
                        for (bit, channel) in [
                            (8, wgpu::ColorWrites::RED),
                            (4, wgpu::ColorWrites::GREEN),
                            (2, wgpu::ColorWrites::BLUE),
                            (1, wgpu::ColorWrites::ALPHA),
                        ] {
                            if bits & bit != 0 {
                                w |= channel;
                            }
                        }
                        w
                    }
                };
                for t in self.targets(state, *target)? {
                    t.write_mask = write_mask;
                }
            }
            StateCommand::Offset { factor, units } => {
                let units = self.float(units);
                if units.fract() != 0.0 {
                    return Err(self.unsupported(format!("fractional depth bias units ({units})")));
                }
                state.depth_bias = wgpu::DepthBiasState {
                    constant: units as i32,
                    slope_scale: self.float(factor) as f32,
                    clamp: 0.0,
                };
            }
            StateCommand::AlphaToMask { on } => state.alpha_to_coverage = self.flag(on),
            StateCommand::Conservative { on } => state.conservative = self.flag(on),
            StateCommand::Stencil { settings } => self.stencil(settings, state)?,
        }
        Ok(())
    }

    fn stencil(&self, settings: &[StencilSetting], state: &mut RenderState) -> Result<(), StateError> {
        let (stencil, reference) = (&mut state.stencil, &mut state.stencil_reference);
        let byte = |value: &StencilValue| match value {
            StencilValue::Byte(Value::Literal(b)) => Some(u32::from(*b)),
            StencilValue::Byte(Value::Property(p)) => Some((self.number)(p).round().clamp(0.0, 255.0) as u32),
            _ => None,
        };
        for setting in settings {
            let value = &setting.value;
            let faces: &mut [&mut wgpu::StencilFaceState] = match setting.field {
                StencilField::Comp | StencilField::Pass | StencilField::Fail | StencilField::ZFail => {
                    &mut [&mut stencil.front, &mut stencil.back]
                }
                StencilField::CompFront
                | StencilField::PassFront
                | StencilField::FailFront
                | StencilField::ZFailFront => &mut [&mut stencil.front],
                StencilField::CompBack
                | StencilField::PassBack
                | StencilField::FailBack
                | StencilField::ZFailBack => &mut [&mut stencil.back],
                StencilField::Ref => {
                    *reference = byte(value).unwrap_or(0);
                    continue;
                }
                StencilField::ReadMask => {
                    stencil.read_mask = byte(value).unwrap_or(0xFF);
                    continue;
                }
                StencilField::WriteMask => {
                    stencil.write_mask = byte(value).unwrap_or(0xFF);
                    continue;
                }
            };
            for face in faces.iter_mut() {
                match (setting.field, value) {
                    (
                        StencilField::Comp | StencilField::CompFront | StencilField::CompBack,
                        StencilValue::Compare(c),
                    ) => {
                        face.compare = self.compare(c)?.unwrap_or(wgpu::CompareFunction::Always);
                    }
                    (
                        StencilField::Pass | StencilField::PassFront | StencilField::PassBack,
                        StencilValue::Operation(o),
                    ) => {
                        face.pass_op = self.stencil_operation(o)?;
                    }
                    (
                        StencilField::Fail | StencilField::FailFront | StencilField::FailBack,
                        StencilValue::Operation(o),
                    ) => {
                        face.fail_op = self.stencil_operation(o)?;
                    }
                    (_, StencilValue::Operation(o)) => face.depth_fail_op = self.stencil_operation(o)?,
                    _ => {}
                }
            }
        }
        Ok(())
    }
}
