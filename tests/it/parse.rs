//! The parser on well-formed input: every fixture parses, and the AST holds what the file says.

use crate::support::{fixture_files, load};
use kiln::diagnostics::render_plain;
use kiln::shaderlab::ast::*;
use kiln::shaderlab::parse_shader;
use kiln::source::SourceStore;

fn parse(text: &str) -> Shader {
    let mut store = SourceStore::new();
    let file = store.add("test.shader", text);
    let parsed = parse_shader(&store, file);
    assert!(parsed.diagnostics.is_empty(), "{}", render_plain(&store, &parsed.diagnostics));
    parsed.shader.expect("parsed")
}

#[test]
fn every_good_fixture_parses_without_diagnostics() {
    let mut files = fixture_files("fixtures/project/shaders", "shader");
    files.extend(fixture_files("fixtures/unity", "shader"));
    assert!(files.len() >= 6);
    let (store, ids, load_errors) = load(&files);
    assert!(load_errors.is_empty());
    for id in ids {
        let parsed = parse_shader(&store, id);
        assert!(parsed.diagnostics.is_empty(), "{}", render_plain(&store, &parsed.diagnostics));
        assert!(parsed.shader.is_some());
    }
}

#[test]
fn lit_shader_structure() {
    let (store, ids, _) = load(&["fixtures/project/shaders/Lit.shader".into()]);
    let shader = parse_shader(&store, ids[0]).shader.expect("parses");
    assert_eq!(shader.name.value, "Custom RP/Lit");
    assert_eq!(store.slice(shader.name.span), "\"Custom RP/Lit\"");
    assert_eq!(shader.properties.len(), 10);
    let clipping = shader.property("_Clipping").expect("_Clipping");
    assert_eq!(clipping.attributes[0].kind, AttributeKind::Toggle(Some("_CLIPPING".into())));
    assert_eq!(store.slice(clipping.attributes[0].span), "[Toggle(_CLIPPING)]");
    let cutoff = shader.property("_Cutoff").expect("_Cutoff");
    assert_eq!(cutoff.ty.value, PropertyType::Range { min: 0.0, max: 1.0 });
    assert_eq!(cutoff.default.value, PropertyDefault::Number(0.5));
    let base_color = shader.property("_BaseColor").expect("_BaseColor");
    assert_eq!(base_color.default.value, PropertyDefault::Vector(vec![0.5, 0.5, 0.5, 1.0]));
    let (_, _, _, pass) = shader.passes().next().expect("one pass");
    assert_eq!(pass.state.tags[0].key.value, "LightMode");
    assert_eq!(pass.state.tags[0].value.value, "CustomLit");
    let blend = &pass.state.render_state[0];
    let RenderCommandKind::Blend { target: None, factors: Some(factors) } = &blend.kind else {
        panic!("expected Blend, got {blend:?}");
    };
    assert_eq!(factors.src.value, Value::Property("_SrcBlend".into()));
    assert_eq!(factors.dst.value, Value::Property("_DstBlend".into()));
    assert_eq!(pass.programs[0].language, ProgramLanguage::Wgsl);
    assert!(pass.programs[0].body.contains("#include \"LitPass.wgsl\""));
    assert_eq!(store.slice(pass.programs[0].body_span), pass.programs[0].body);
    assert_eq!(shader.custom_editors[0].class.value, "CustomShaderGUI");
}

#[test]
fn keywords_are_case_insensitive_and_commands_share_lines() {
    let shader = parse(
        "shader \"s\" { properties { _A (\"a\", float) = .7 _C (\"c\", color) = (1, .5, .5) }
         subshader { tags{\"Queue\"=\"Geometry+1\"} pass { name \"P/1 (x)\" blend one zero zwrite off cull front } }
         fallback off }",
    );
    assert_eq!(shader.properties[0].default.value, PropertyDefault::Number(0.7));
    assert_eq!(shader.properties[1].default.value, PropertyDefault::Vector(vec![1.0, 0.5, 0.5]));
    let (_, sub, _, pass) = shader.passes().next().expect("pass");
    assert_eq!(sub.state.tags[0].value.value, "Geometry+1");
    assert_eq!(pass.state.name.as_ref().map(|n| n.value.as_str()), Some("P/1 (x)"));
    let kinds: Vec<&str> = pass.state.render_state.iter().map(|c| c.kind.keyword()).collect();
    assert_eq!(kinds, ["Blend", "ZWrite", "Cull"]);
    assert!(matches!(shader.fallback, Some(Fallback::Off(_))));
}

#[test]
fn render_state_commands_in_full() {
    let shader = parse(
        "Shader \"s\" { SubShader { Pass {
            Blend 1 SrcAlpha OneMinusSrcAlpha, One Zero
            Blend 2 Off
            BlendOp RevSub, Max
            ZTest GEqual  ZClip False  Conservative True  AlphaToMask On
            ColorMask RB 3
            Offset -1.5, [_Units]
            Stencil { Ref [_Ref] ReadMask 15 Comp NotEqual PassFront IncrWrap ZFailBack Invert }
        } } }",
    );
    let (_, _, _, pass) = shader.passes().next().expect("pass");
    let state: Vec<&RenderCommandKind> = pass.state.render_state.iter().map(|c| &c.kind).collect();
    match state[0] {
        RenderCommandKind::Blend { target: Some(1), factors: Some(f) } => {
            assert_eq!(f.src.value, Value::Literal(BlendFactor::SrcAlpha));
            let (a, b) = f.alpha.as_ref().expect("separate alpha");
            assert_eq!(
                (a.value.clone(), b.value.clone()),
                (Value::Literal(BlendFactor::One), Value::Literal(BlendFactor::Zero))
            );
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(state[1], RenderCommandKind::Blend { target: Some(2), factors: None }));
    match state[2] {
        RenderCommandKind::BlendOp { color, alpha: Some(alpha), .. } => {
            assert_eq!(color.value, Value::Literal(BlendOperation::RevSub));
            assert_eq!(alpha.value, Value::Literal(BlendOperation::Max));
        }
        other => panic!("{other:?}"),
    }
    assert!(
        matches!(&state[3], RenderCommandKind::ZTest(v) if v.value == Value::Literal(CompareFunction::GEqual))
    );
    assert!(matches!(&state[4], RenderCommandKind::ZClip(v) if v.value == Value::Literal(false)));
    assert!(matches!(&state[5], RenderCommandKind::Conservative(v) if v.value == Value::Literal(true)));
    assert!(matches!(&state[6], RenderCommandKind::AlphaToMask(v) if v.value == Value::Literal(true)));
    assert!(matches!(&state[7], RenderCommandKind::ColorMask { mask, target: Some(3) }
        if mask.value == Value::Literal(ColorMask { r: true, g: false, b: true, a: false })));
    assert!(matches!(&state[8], RenderCommandKind::Offset { factor, units }
        if factor.value == Value::Literal(-1.5) && units.value == Value::Property("_Units".into())));
    let RenderCommandKind::Stencil(entries) = state[9] else { panic!("{:?}", state[9]) };
    let ops: Vec<StencilField> = entries.iter().map(|e| e.op).collect();
    assert_eq!(
        ops,
        [
            StencilField::Ref,
            StencilField::ReadMask,
            StencilField::Comp,
            StencilField::PassFront,
            StencilField::ZFailBack
        ]
    );
    assert_eq!(entries[0].value.value, StencilValue::Byte(Value::Property("_Ref".into())));
    assert_eq!(entries[1].value.value, StencilValue::Byte(Value::Literal(15)));
    assert_eq!(entries[2].value.value, StencilValue::Compare(Value::Literal(CompareFunction::NotEqual)));
}

#[test]
fn messy_legacy_file() {
    let (store, ids, _) = load(&["fixtures/unity/LegacyMessy.shader".into()]);
    let shader = parse_shader(&store, ids[0]).shader.expect("parses");
    assert!(!store.text(ids[0]).ends_with('\n'), "the fixture has no final newline");
    assert!(store.text(ids[0]).contains('\t'));
    assert_eq!(shader.categories.len(), 1);
    assert_eq!(shader.subshaders.len(), 2);
    assert!(shader.subshaders.iter().all(|s| s.category == Some(0)));
    let category = &shader.categories[0].state;
    assert_eq!(category.render_state.len(), 3, "Blend, ZWrite and Cull on one line");
    assert_eq!(
        category.legacy.iter().map(|l| l.keyword.value.as_str()).collect::<Vec<_>>(),
        ["Lighting", "Fog"]
    );
    let (_, _, _, pass) = shader.passes().next().expect("pass");
    let legacy: Vec<&str> = pass.state.legacy.iter().map(|l| l.keyword.value.as_str()).collect();
    assert_eq!(
        legacy,
        [
            "Lighting",
            "SeparateSpecular",
            "ColorMaterial",
            "AlphaTest",
            "Color",
            "Material",
            "BindChannels",
            "SetTexture",
            "SetTexture"
        ]
    );
    let color = shader.property("_Color").expect("_Color");
    assert_eq!(color.attributes[0].kind, AttributeKind::Hdr);
    assert_eq!(color.default.value, PropertyDefault::Vector(vec![1.0, 0.5, 0.5]));
    let glow = shader.property("_Glow").expect("_Glow");
    assert_eq!(
        glow.attributes.iter().map(|a| a.kind.clone()).collect::<Vec<_>>(),
        [AttributeKind::Hdr, AttributeKind::Gamma]
    );
    let main_tex = shader.property("_MainTex").expect("_MainTex");
    assert_eq!(
        main_tex.default.value,
        PropertyDefault::Texture { name: String::new(), options: Some("TexGen CubeReflect".into()) }
    );
    let odd = shader.property("_Odd").expect("_Odd");
    assert_eq!(odd.default.value, PropertyDefault::Texture { name: "my-texture.png".into(), options: None });
    assert_eq!(
        shader.property("_Shift").expect("_Shift").default.value,
        PropertyDefault::Vector(vec![0.1, -0.2, 3.0, 0.01])
    );
    assert!(matches!(shader.fallback, Some(Fallback::Off(_))));
}

#[test]
fn drawers_and_unknown_attributes() {
    let (store, ids, _) =
        load(&["fixtures/unity/UniversalLit.shader".into(), "fixtures/unity/SurfaceToon.shader".into()]);
    let urp = parse_shader(&store, ids[0]).shader.expect("parses");
    let detail = urp.property("_Detail").expect("_Detail");
    assert_eq!(
        detail.attributes[0].kind,
        AttributeKind::KeywordEnum(vec!["Off".into(), "Simple".into(), "Full".into()])
    );
    assert_eq!(
        urp.property("_Shininess").expect("_Shininess").attributes[0].kind,
        AttributeKind::PowerSlider(3.0)
    );
    assert_eq!(
        urp.property("_SpecularHighlights").expect("p").attributes[0].kind,
        AttributeKind::ToggleOff(None)
    );
    let custom = &urp.property("_Custom").expect("_Custom").attributes[0];
    assert_eq!(custom.kind, AttributeKind::Other);
    assert_eq!(custom.name.value, "CustomDrawer");
    assert_eq!(custom.args.iter().map(|a| store.slice(a.span)).collect::<Vec<_>>(), ["some", "args"]);
    let stencil_ref = urp.property("_StencilRef").expect("_StencilRef");
    assert_eq!(stencil_ref.attributes[0].kind, AttributeKind::Header("Stencil".into()));
    assert_eq!(stencil_ref.attributes[1].kind, AttributeKind::IntRange);
    assert_eq!(urp.includes.len(), 1);
    assert_eq!(urp.includes[0].language, ProgramLanguage::Hlsl);
    assert_eq!(urp.subshaders[0].state.package_requirements.len(), 2);
    assert_eq!(
        urp.custom_editors[1].render_pipeline.as_ref().map(|p| p.value.as_str()),
        Some("UnityEngine.Rendering.Universal.UniversalRenderPipelineAsset")
    );
    assert_eq!(urp.dependencies[0].name.value, "BaseMapShader");
    let Some(Fallback::Shader(fallback)) = &urp.fallback else { panic!("fallback") };
    assert_eq!(fallback.value, "Hidden/Universal Render Pipeline/FallbackError");

    let toon = parse_shader(&store, ids[1]).shader.expect("parses");
    assert_eq!(toon.property("_Outline").expect("p").attributes[0].kind, AttributeKind::Toggle(None));
    assert!(matches!(toon.property("_CullMode").expect("p").attributes[0].kind, AttributeKind::Enum(_)));
    assert_eq!(toon.property("_RimColor").expect("p").attributes[0].kind, AttributeKind::Hdr);
    let sub = &toon.subshaders[0];
    assert_eq!(sub.programs.len(), 1, "the surface program sits in the SubShader");
    assert!(!sub.programs[0].is_include);
    assert!(
        matches!(&sub.passes[0], PassItem::GrabPass(g) if g.texture.as_ref().is_some_and(|t| t.value == "_BackgroundTexture"))
    );
    assert!(
        matches!(&sub.passes[1], PassItem::UsePass(name) if name.value == "Legacy Shaders/VertexLit/SHADOWCASTER")
    );
}

#[test]
fn placeholder_may_come_last() {
    let (store, ids, _) = load(&["fixtures/unity/SurfaceToon.shader".into()]);
    let shader = parse_shader(&store, ids[0]).shader.expect("parses");
    let (_, sub, _, forward) = shader
        .passes()
        .find(|(_, _, _, p)| p.state.name.as_ref().is_some_and(|n| n.value == "FORWARD"))
        .expect("FORWARD");
    let (pragmas, diagnostics) = kiln::shaderlab::pragma::collect_pragmas(
        kiln::listing::program_blocks(&shader, sub, &forward.programs)
            .into_iter()
            .map(kiln::shaderlab::pragma::PragmaSource::from),
    );
    assert!(diagnostics.is_empty());
    let toon =
        pragmas.keyword_sets.iter().find(|s| s.keywords().any(|k| k == "_TOON_RAMP")).expect("toon set");
    let options: Vec<Option<&str>> = toon.options.iter().map(|o| o.keyword.as_deref()).collect();
    assert_eq!(options, [Some("_TOON_RAMP"), Some("_TOON_SOFT"), None]);
    assert!(toon.has_off_option());
}

/// The constructs of real Unity files that Unity accepts and kiln once refused, read as Unity
/// reads them (tests/corpus/unity holds the files they come from).
#[test]
fn unity_s_quirks_read_as_unity_reads_them() {
    let text = "Shader \"Quirks\" {\n    Properties {\n        \
        [Enum(PBR(Unity Metallic Standard),0,Baked Cubemap,1)] _Mode (\"Mode\", Int) = 0\n        \
        [Header(Color Modifier (By Speed))] _Speed (\"Speed\", Float) = 1\n        \
        _Preset (\"Rendering Preset--{on_value_actions:[\n            {value:0,actions:[]}\n        ]}\", Int) = 0\n        \
        _Forward (\"Forward\", Vector) = (0, 0, 1)\n    }\n    \
        SubShader {\n        Pass {\n            ZTest Off\n        }\n    }\n}\n";
    let shader = parse(text);
    let mode = shader.property("_Mode").expect("_Mode");
    assert_eq!(
        mode.attributes[0].kind,
        AttributeKind::Enum(vec![
            "PBR(Unity Metallic Standard)".into(),
            "0".into(),
            "Baked Cubemap".into(),
            "1".into()
        ])
    );
    let speed = shader.property("_Speed").expect("_Speed");
    assert_eq!(speed.attributes[0].kind, AttributeKind::Header("Color Modifier (By Speed)".into()));
    let preset = shader.property("_Preset").expect("_Preset");
    assert_eq!(
        preset.display_name.value,
        "Rendering Preset--{on_value_actions:[\n            {value:0,actions:[]}\n        ]}"
    );
    let forward = shader.property("_Forward").expect("_Forward");
    assert_eq!(forward.default.value, PropertyDefault::Vector(vec![0.0, 0.0, 1.0, 0.0]));
    let PassItem::Pass(pass) = &shader.subshaders[0].passes[0] else { panic!("a pass") };
    assert!(matches!(
        &pass.state.render_state[0].kind,
        RenderCommandKind::ZTest(z) if z.value == Value::Literal(kiln::manifest::state::CompareFunction::Always)
    ));
}

/// A string that is not a display name still ends on its line: a missing quote is found where it
/// is, not at the next quote lines below.
#[test]
fn only_a_display_name_runs_over_lines() {
    let mut store = SourceStore::new();
    let text = "Shader \"Broken {\n    Properties {\n        _A (\"A\", Float) = 0\n    }\n}\n";
    let file = store.add("broken.shader", text);
    let parsed = parse_shader(&store, file);
    assert!(
        parsed.diagnostics.iter().any(|d| d.code == "K0101"),
        "{}",
        render_plain(&store, &parsed.diagnostics)
    );
}
