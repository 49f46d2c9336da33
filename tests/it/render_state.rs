//! Render state through both crates: ShaderLab commands as the compiler's parser reads them,
//! through the manifest's JSON, to the wgpu state the run time resolves.

use kiln::manifest::{PassManifest, PropertyReference, RenderState as Command};
use kiln::runtime::resolve_render_state;

/// A pass with these commands, parsed by kiln's ShaderLab parser as a build would.
fn pass(commands: &[&str]) -> PassManifest {
    let mut store = kiln::source::SourceStore::new();
    let text = format!("Shader \"state\" {{ SubShader {{ Pass {{\n{}\n}} }} }}", commands.join("\n"));
    let file = store.add("render state", text);
    let parsed = kiln::shaderlab::parse_shader(&store, file);
    assert!(parsed.diagnostics.is_empty(), "{:?}", parsed.diagnostics);
    let shader = parsed.shader.expect("parses");
    let (_, _, _, ast) = shader.passes().next().expect("a pass");
    let render_state: Vec<Command> = ast
        .state
        .render_state
        .iter()
        .map(|c| Command {
            command: store.slice(c.span).trim().to_string(),
            state: c.kind.to_manifest(),
            properties: vec![PropertyReference { name: "_ZTest".into(), default: serde_json::json!(4.0) }],
        })
        .collect();
    // Through JSON, as the runtime reads a manifest.
    let render_state =
        serde_json::from_value(serde_json::to_value(&render_state).expect("serializes")).expect("reads back");
    PassManifest {
        subshader: 0,
        index: 0,
        name: None,
        tags: Vec::new(),
        render_state,
        keyword_sets: Vec::new(),
        keywords: Vec::new(),
        kernels: Vec::new(),
        layout: Vec::new(),
        uniform_blocks: Vec::new(),
        packs: Vec::new(),
        interfaces: Vec::new(),
        modules: Vec::new(),
        variants: Vec::new(),
        ubershader: None,
    }
}

#[test]
fn every_command_reaches_its_wgpu_state() {
    let commands = [
        "Blend SrcAlpha OneMinusSrcAlpha, One OneMinusSrcAlpha",
        "Blend 1 Off",
        "BlendOp RevSub",
        "ZWrite Off",
        "ZTest [_ZTest]",
        "Cull [_Cull]",
        "ColorMask RG 2",
        "Offset -1, -2",
        "AlphaToMask On",
        "Stencil { Ref 3 ReadMask 15 Comp Equal Pass Replace ZFailBack IncrWrap }",
    ];
    let values = |name: &str| match name {
        "_ZTest" => Some(8.0),
        "_Cull" => Some(1.0),
        _ => None,
    };
    let state = resolve_render_state(&pass(&commands), &values).expect("resolves");
    let blend = state.targets[0].blend.expect("blends");
    assert_eq!(blend.color.src_factor, wgpu::BlendFactor::SrcAlpha);
    assert_eq!(blend.alpha.src_factor, wgpu::BlendFactor::One);
    assert_eq!(blend.color.operation, wgpu::BlendOperation::ReverseSubtract);
    assert_eq!(
        state.targets[1].blend.map(|b| b.color.operation),
        Some(wgpu::BlendOperation::ReverseSubtract)
    );
    assert_eq!(state.targets[2].write_mask, wgpu::ColorWrites::RED | wgpu::ColorWrites::GREEN);
    assert_eq!(state.targets[0].write_mask, wgpu::ColorWrites::ALL);
    assert!(!state.depth_write);
    assert_eq!(state.depth_compare, Some(wgpu::CompareFunction::Always));
    assert_eq!(state.cull_mode, Some(wgpu::Face::Front));
    assert_eq!((state.depth_bias.constant, state.depth_bias.slope_scale), (-2, -1.0));
    assert!(state.alpha_to_coverage);
    assert_eq!((state.stencil_reference, state.stencil.read_mask), (3, 15));
    assert_eq!(state.stencil.front.compare, wgpu::CompareFunction::Equal);
    assert_eq!(state.stencil.back.pass_op, wgpu::StencilOperation::Replace);
    assert_eq!(state.stencil.back.depth_fail_op, wgpu::StencilOperation::IncrementWrap);
    assert_eq!(state.stencil.front.depth_fail_op, wgpu::StencilOperation::Keep);
    // The manifest's default for a property the material lacks.
    let state = resolve_render_state(&pass(&["ZTest [_ZTest]"]), &|_| None).expect("resolves");
    assert_eq!(state.depth_compare, Some(wgpu::CompareFunction::LessEqual));
}

#[test]
fn what_wgpu_cannot_express_is_an_error_naming_the_command() {
    let error = resolve_render_state(&pass(&["BlendOp LogicalXor"]), &|_| None).expect_err("refused");
    assert!(error.to_string().contains("`BlendOp LogicalXor`"), "{error}");
    let error = resolve_render_state(&pass(&["Blend [_Src] Zero"]), &|_| Some(42.0)).expect_err("refused");
    assert!(error.to_string().contains("property `_Src` is 42, which is not a blend factor"), "{error}");
    let error = resolve_render_state(&pass(&["Offset 0, 0.5"]), &|_| None).expect_err("refused");
    assert!(error.to_string().contains("fractional depth bias units"), "{error}");
}
