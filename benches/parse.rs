//! Parsing speed on a generated 1 MB shader: many properties and passes with program blocks.
//! Run with `cargo bench --bench parse`; criterion reports time and throughput.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use kiln::source::SourceStore;
use std::fmt::Write as _;

/// A shader of at least `bytes` bytes, shaped like real files: properties with drawers, then
/// passes with tags, render state, a stencil block and a WGSL program with pragmas.
fn big_shader(bytes: usize) -> String {
    let mut text = String::from("Shader \"Bench/Big\" {\n    Properties {\n");
    for i in 0..2000 {
        let _ = writeln!(text, "        [Toggle(_FEATURE_{i})] _Feature{i} (\"Feature {i}\", Float) = 0");
        let _ = writeln!(text, "        [HDR] _Tint{i} (\"Tint {i}\", Color) = (1, 0.5, 0.25, 1)");
    }
    text.push_str("    }\n    SubShader {\n        Tags { \"RenderType\" = \"Opaque\" }\n");
    let mut pass = 0;
    while text.len() < bytes {
        let _ = write!(
            text,
            r#"        Pass {{
            Name "Pass{pass}"
            Tags {{ "LightMode" = "Mode{pass}" }}
            Blend [_SrcBlend] [_DstBlend], One OneMinusSrcAlpha
            ZWrite Off Cull Back ZTest LEqual ColorMask RGB
            Stencil {{ Ref 2 Comp Always Pass Replace }}
            WGSLPROGRAM
            #pragma target 3.5
            #pragma shader_feature_local _ _A{pass} _B{pass}
            #pragma multi_compile_fragment _ _C{pass}
            #pragma vertex vs_main
            #pragma fragment fs_main
            @vertex fn vs_main(@location(0) p: vec3<f32>) -> @builtin(position) vec4<f32> {{
                return vec4<f32>(p, 1.0);
            }}
            @fragment fn fs_main() -> @location(0) vec4<f32> {{ return vec4<f32>(1.0); }}
            ENDWGSL
        }}
"#
        );
        pass += 1;
    }
    text.push_str("    }\n}\n");
    text
}

fn parse(c: &mut Criterion) {
    let text = big_shader(1 << 20);
    let mut store = SourceStore::new();
    let file = store.add("big.shader", text.clone());
    let mut group = c.benchmark_group("parse_1mb");
    group.throughput(Throughput::Bytes(text.len() as u64));
    group.sample_size(20);
    group.bench_function("parse_shader", |b| {
        b.iter(|| {
            let parsed = kiln::shaderlab::parse_shader(&store, file);
            assert!(parsed.diagnostics.is_empty());
            parsed
        })
    });
    group.bench_function("list_shaders", |b| {
        b.iter(|| {
            kiln::listing::list_shaders(
                &mut store,
                &mut kiln::preprocess::Includes::new(kiln::preprocess::IncludeConfig::new(Vec::new())),
                &kiln::catalog::CatalogInput { shaders: vec![file], ..Default::default() },
            )
        })
    });
    group.finish();
}

criterion_group!(benches, parse);
criterion_main!(benches);
