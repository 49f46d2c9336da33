//! Host-shareable layouts against the WGSL spec's rules, written here from the spec's text
//! (§ Memory Layout, § Address Space Layout Constraints) and sharing nothing with kiln or naga.
//! Seeded random structs (nested structs, arrays of structs and of arrays, vec3 + scalar packing,
//! matrices, f16, `@align`/`@size`, runtime-sized arrays) are built as uniform and storage
//! blocks, and every output is compared with the reference: the manifest, the generated Rust's
//! size and offset assertions, the SPIR-V decorations (read from the binary here), the WGSL kiln
//! writes (its structs parsed here and laid out by the reference), and naga reading that WGSL
//! again. Structs the spec refuses must be refused; those naga's SPIR-V writer cannot express
//! ship as WGSL only, with a warning naming the member (K0415). A GPU round trip (lavapipe in CI) fills a sample of blocks at the reference's offsets and reads every
//! scalar back through kiln's WGSL.

use crate::support::{gpu, tool};
use kiln::config::VariantSelection;
use kiln::manifest::Manifest;
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

// ---------------------------------------------------------------------------------------------
// The model and the spec's layout rules.

#[derive(Debug, Clone, PartialEq)]
enum Ty {
    /// `f32`, `i32`, `u32` or `f16`.
    Scalar(&'static str),
    Vector(u32, &'static str),
    Matrix(u32, u32, &'static str),
    /// `None`: runtime-sized.
    Array(Box<Ty>, Option<u32>),
    Struct(String),
}

#[derive(Debug, Clone, PartialEq)]
struct MemberDef {
    name: String,
    ty: Ty,
    align: Option<u32>,
    size: Option<u32>,
}

#[derive(Debug, Clone, PartialEq)]
struct StructDef {
    name: String,
    members: Vec<MemberDef>,
}

type Structs = BTreeMap<String, StructDef>;

fn round_up(k: u32, n: u32) -> u32 {
    n.div_ceil(k) * k
}

fn width(scalar: &str) -> u32 {
    if scalar == "f16" { 2 } else { 4 }
}

/// AlignOf(T), from the spec's table.
fn align_of(ty: &Ty, structs: &Structs) -> u32 {
    match ty {
        Ty::Scalar(s) => width(s),
        Ty::Vector(n, s) => (if *n == 2 { 2 } else { 4 }) * width(s),
        Ty::Matrix(_, rows, s) => align_of(&Ty::Vector(*rows, s), structs),
        Ty::Array(element, _) => align_of(element, structs),
        Ty::Struct(name) => structs[name]
            .members
            .iter()
            .map(|m| m.align.unwrap_or_else(|| align_of(&m.ty, structs)))
            .max()
            .unwrap_or(1),
    }
}

/// SizeOf(T); a runtime-sized array counts as no bytes (where a struct's fixed part ends).
fn size_of(ty: &Ty, structs: &Structs) -> u32 {
    match ty {
        Ty::Scalar(s) => width(s),
        Ty::Vector(n, s) => n * width(s),
        Ty::Matrix(columns, rows, s) => columns * stride_of(&Ty::Vector(*rows, s), structs),
        Ty::Array(element, Some(n)) => n * stride_of(element, structs),
        Ty::Array(_, None) => 0,
        Ty::Struct(name) => {
            let def = &structs[name];
            let offsets = offsets(def, structs);
            let last = def.members.len() - 1;
            let end = offsets[last] + member_size(&def.members[last], structs);
            round_up(align_of(ty, structs), end)
        }
    }
}

/// The element stride of an array of T (and the column stride of a matrix of T columns).
fn stride_of(element: &Ty, structs: &Structs) -> u32 {
    round_up(align_of(element, structs), size_of(element, structs))
}

fn member_size(member: &MemberDef, structs: &Structs) -> u32 {
    member.size.unwrap_or_else(|| size_of(&member.ty, structs))
}

/// OffsetOfMember for each member.
fn offsets(def: &StructDef, structs: &Structs) -> Vec<u32> {
    let mut out = Vec::new();
    let mut end = 0;
    for member in &def.members {
        let offset = round_up(member.align.unwrap_or_else(|| align_of(&member.ty, structs)), end);
        out.push(offset);
        end = offset + member_size(member, structs);
    }
    out
}

/// RequiredAlignOf(T, uniform).
fn uniform_required_align(ty: &Ty, structs: &Structs) -> u32 {
    match ty {
        Ty::Array(..) | Ty::Struct(_) => round_up(16, align_of(ty, structs)),
        _ => align_of(ty, structs),
    }
}

/// The address-space layout constraints of the uniform address space, or the first broken one.
fn uniform_violation(ty: &Ty, structs: &Structs) -> Option<String> {
    match ty {
        Ty::Array(_, None) => Some("a runtime-sized array in a uniform buffer".into()),
        Ty::Array(element, Some(_)) => {
            let stride = stride_of(element, structs);
            if !stride.is_multiple_of(uniform_required_align(element, structs)) || !stride.is_multiple_of(16)
            {
                return Some(format!("array stride {stride} is not a multiple of 16"));
            }
            uniform_violation(element, structs)
        }
        Ty::Struct(name) => {
            let def = &structs[name];
            let offsets = offsets(def, structs);
            for (i, member) in def.members.iter().enumerate() {
                if !offsets[i].is_multiple_of(uniform_required_align(&member.ty, structs)) {
                    return Some(format!("{name}.{} at offset {}", member.name, offsets[i]));
                }
                if let (Ty::Struct(_), Some(next)) = (&member.ty, offsets.get(i + 1))
                    && next - offsets[i] < round_up(16, size_of(&member.ty, structs))
                {
                    return Some(format!("{name}.{} is followed too closely", member.name));
                }
                if let Some(problem) = uniform_violation(&member.ty, structs) {
                    return Some(problem);
                }
            }
            None
        }
        _ => None,
    }
}

/// What kiln ships as WGSL only in uniform buffers because naga's SPIR-V writer cannot express it
/// (docs/diagnostics.md, K0415): the member it names, or `None`.
fn kiln_refusal(ty: &Ty, structs: &Structs, nested: bool) -> Option<String> {
    let Ty::Struct(name) = ty else { return None };
    structs[name].members.iter().find_map(|m| {
        let mut innermost = &m.ty;
        while let Ty::Array(element, _) = innermost {
            innermost = element;
        }
        match innermost {
            Ty::Matrix(_, rows, "f16") if *rows > 2 => Some(format!("{name}.{}", m.name)),
            Ty::Matrix(_, 2, _) if nested => Some(format!("{name}.{}", m.name)),
            Ty::Struct(_) => kiln_refusal(innermost, structs, true),
            _ => None,
        }
    })
}

// ---------------------------------------------------------------------------------------------
// Generated cases.

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        // splitmix64
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: u32) -> u32 {
        (self.next() % u64::from(n)) as u32
    }
    fn chance(&mut self, percent: u32) -> bool {
        self.below(100) < percent
    }
}

#[derive(Debug, Clone)]
struct Case {
    index: usize,
    uniform: bool,
    half: bool,
    /// In declaration order; the last is the block's type.
    structs: Vec<StructDef>,
}

impl Case {
    fn structs(&self) -> Structs {
        self.structs.iter().map(|s| (s.name.clone(), s.clone())).collect()
    }
    fn root(&self) -> Ty {
        Ty::Struct(self.structs.last().expect("a struct").name.clone())
    }
    fn shader_name(&self) -> String {
        format!("Layout/Case{}", self.index)
    }
}

fn random_plain(rng: &mut Rng, half: bool) -> Ty {
    let scalars: &[&'static str] =
        if half { &["f32", "i32", "u32", "f16", "f16"] } else { &["f32", "i32", "u32"] };
    let scalar = scalars[rng.below(scalars.len() as u32) as usize];
    match rng.below(10) {
        0..=2 => Ty::Scalar(scalar),
        3..=6 => Ty::Vector(2 + rng.below(3), scalar),
        _ => {
            let float = if half && rng.chance(40) { "f16" } else { "f32" };
            Ty::Matrix(2 + rng.below(3), 2 + rng.below(3), float)
        }
    }
}

fn random_type(rng: &mut Rng, half: bool, earlier: &[StructDef]) -> Ty {
    let element = |rng: &mut Rng| {
        if !earlier.is_empty() && rng.chance(40) {
            Ty::Struct(earlier[rng.below(earlier.len() as u32) as usize].name.clone())
        } else {
            random_plain(rng, half)
        }
    };
    match rng.below(10) {
        0..=4 => random_plain(rng, half),
        5 | 6 => Ty::Array(Box::new(element(rng)), Some(1 + rng.below(4))),
        7 => Ty::Array(
            Box::new(Ty::Array(Box::new(element(rng)), Some(1 + rng.below(3)))),
            Some(1 + rng.below(3)),
        ),
        _ => element(rng),
    }
}

/// `a`, `b`, ...: names that do not end in a digit, which naga's writer would rename.
fn letter(i: usize) -> char {
    (b'a' + i as u8) as char
}

fn random_case(index: usize, rng: &mut Rng) -> Case {
    let uniform = rng.chance(50);
    let half = rng.chance(30);
    let count = 1 + rng.below(4) as usize;
    let mut case = Case { index, uniform, half, structs: Vec::new() };
    for k in 0..count {
        let members = 1 + rng.below(6) as usize;
        let mut def = StructDef { name: format!("L{index}{}", letter(k)), members: Vec::new() };
        for j in 0..members {
            let ty = random_type(rng, half, &case.structs);
            def.members.push(MemberDef { name: format!("m{}", letter(j)), ty, align: None, size: None });
        }
        let is_root = k + 1 == count;
        if is_root && !uniform && rng.chance(30) {
            let element = random_type(rng, half, &case.structs);
            let element = match element {
                Ty::Array(inner, _) => *inner,
                other => other,
            };
            def.members.push(MemberDef {
                name: format!("m{}", letter(members)),
                ty: Ty::Array(Box::new(element), None),
                align: None,
                size: None,
            });
        }
        case.structs.push(def);
        // Attributes once the struct's members are known (their types' layouts need them).
        let structs = case.structs();
        let def = case.structs.last_mut().expect("just pushed");
        for member in &mut def.members {
            let runtime = matches!(member.ty, Ty::Array(_, None));
            if rng.chance(25) {
                // A multiple of what the address space requires, as the spec demands of `@align`.
                let base = if uniform {
                    uniform_required_align(&member.ty, &structs)
                } else {
                    align_of(&member.ty, &structs)
                };
                member.align = Some(base << rng.below(4));
            }
            if !runtime && rng.chance(20) {
                let extra = [0, 1, 2, 4, 8, 12, 16, 20, 32][rng.below(9) as usize];
                member.size = Some(size_of(&member.ty, &structs) + extra);
            }
        }
    }
    case
}

/// The spec's own examples (WGSL § Memory Layout), with the numbers the spec gives.
/// A struct of a spec example: its name, member offsets, size and alignment as the spec gives them.
type SpecNumbers = (&'static str, Vec<u32>, u32, u32);

fn spec_examples() -> Vec<(Case, Vec<SpecNumbers>)> {
    let member = |name: &str, ty: Ty, align: Option<u32>, size: Option<u32>| MemberDef {
        name: name.to_string(),
        ty,
        align,
        size,
    };
    let f = || Ty::Scalar("f32");
    let a = |name: &str, sized: bool| StructDef {
        name: name.to_string(),
        members: vec![
            member("u", f(), None, None),
            member("v", f(), None, None),
            member("w", Ty::Vector(2, "f32"), None, None),
            member("x", f(), None, sized.then_some(16)),
        ],
    };
    let b = |name: &str, a: &str, aligned: bool| StructDef {
        name: name.to_string(),
        members: vec![
            member("a", Ty::Vector(2, "f32"), None, None),
            member("b", Ty::Vector(3, "f32"), None, None),
            member("c", f(), None, None),
            member("d", f(), None, None),
            member("e", Ty::Struct(a.to_string()), aligned.then_some(16), None),
            member("f", Ty::Vector(3, "f32"), None, None),
            member("g", Ty::Array(Box::new(Ty::Struct(a.to_string())), Some(3)), None, None),
            member("h", Ty::Scalar("i32"), None, None),
        ],
    };
    vec![
        (
            Case {
                index: 10_000,
                uniform: false,
                half: false,
                structs: vec![a("SpecA", false), b("SpecB", "SpecA", false)],
            },
            vec![
                ("SpecA", vec![0, 4, 8, 16], 24, 8),
                ("SpecB", vec![0, 16, 28, 32, 40, 64, 80, 152], 160, 16),
            ],
        ),
        (
            Case {
                index: 10_001,
                uniform: false,
                half: false,
                structs: vec![a("SpecSizedA", true), b("SpecAlignedB", "SpecSizedA", true)],
            },
            vec![
                ("SpecSizedA", vec![0, 4, 8, 16], 32, 8),
                ("SpecAlignedB", vec![0, 16, 28, 32, 48, 80, 96, 192], 208, 16),
            ],
        ),
    ]
}

// ---------------------------------------------------------------------------------------------
// WGSL text: the shader a case becomes, and the reads that use every member.

fn wgsl_type(ty: &Ty) -> String {
    match ty {
        Ty::Scalar(s) => s.to_string(),
        Ty::Vector(n, s) => format!("vec{n}<{s}>"),
        Ty::Matrix(c, r, s) => format!("mat{c}x{r}<{s}>"),
        Ty::Array(e, Some(n)) => format!("array<{}, {n}>", wgsl_type(e)),
        Ty::Array(e, None) => format!("array<{}>", wgsl_type(e)),
        Ty::Struct(name) => name.clone(),
    }
}

fn struct_declarations(case: &Case) -> String {
    let mut out = String::new();
    for def in &case.structs {
        let _ = writeln!(out, "struct {} {{", def.name);
        for m in &def.members {
            let align = m.align.map(|a| format!("@align({a}) ")).unwrap_or_default();
            let size = m.size.map(|s| format!("@size({s}) ")).unwrap_or_default();
            let _ = writeln!(out, "    {align}{size}{}: {},", m.name, wgsl_type(&m.ty));
        }
        out.push_str("}\n");
    }
    out
}

/// Every scalar of a value of type `ty` at `path`, with its offset from the block's start and
/// its scalar type; arrays read at every index (a runtime-sized one at two).
fn leaves(ty: &Ty, path: &str, offset: u32, structs: &Structs, out: &mut Vec<(String, u32, &'static str)>) {
    match ty {
        Ty::Scalar(s) => out.push((path.to_string(), offset, s)),
        Ty::Vector(n, s) => {
            for i in 0..*n {
                out.push((format!("{path}[{i}]"), offset + i * width(s), s));
            }
        }
        Ty::Matrix(c, r, s) => {
            let stride = stride_of(&Ty::Vector(*r, s), structs);
            for column in 0..*c {
                leaves(
                    &Ty::Vector(*r, s),
                    &format!("{path}[{column}]"),
                    offset + column * stride,
                    structs,
                    out,
                );
            }
        }
        Ty::Array(element, length) => {
            let stride = stride_of(element, structs);
            for i in 0..length.unwrap_or(2) {
                leaves(element, &format!("{path}[{i}]"), offset + i * stride, structs, out);
            }
        }
        Ty::Struct(name) => {
            let def = &structs[name];
            for (member, at) in def.members.iter().zip(offsets(def, structs)) {
                leaves(&member.ty, &format!("{path}.{}", member.name), offset + at, structs, out);
            }
        }
    }
}

/// A fragment stage that loads every member: whole matrices and structs as values too, which is
/// where naga's SPIR-V writer has failed.
fn reads(case: &Case) -> String {
    let structs = case.structs();
    let mut out = String::new();
    let mut found = Vec::new();
    leaves(&case.root(), "blk", 0, &structs, &mut found);
    for (path, _, scalar) in found.iter().take(160) {
        let _ = writeln!(out, "    acc += f32({path});{}", if *scalar == "f16" { " // f16" } else { "" });
    }
    let root = &structs[&case.structs.last().expect("root").name];
    for member in &root.members {
        match &member.ty {
            Ty::Matrix(..) | Ty::Struct(_) => {
                let _ = writeln!(out, "    let whole_{0} = blk.{0};", member.name);
                let _ = writeln!(out, "    _ = whole_{};", member.name);
            }
            _ => {}
        }
    }
    out
}

fn shader(case: &Case) -> String {
    let space = if case.uniform { "uniform" } else { "storage, read" };
    let (require, enable) =
        if case.half { ("            #pragma require native16bit\n", "enable f16;\n") } else { ("", "") };
    format!(
        "Shader \"{name}\"\n{{\n    SubShader\n    {{\n        Pass\n        {{\n            WGSLPROGRAM\n            #pragma vertex Vertex\n            #pragma fragment Fragment\n{require}{enable}{structs}\nvar<{space}> blk: {root};\n\n@vertex fn Vertex(@location(0) p: vec3<f32>) -> @builtin(position) vec4<f32> {{\n    return vec4<f32>(p, 1.0);\n}}\n\n@fragment fn Fragment() -> @location(0) vec4<f32> {{\n    var acc = 0.0;\n{reads}    return vec4<f32>(acc);\n}}\n            ENDWGSL\n        }}\n    }}\n}}\n",
        name = case.shader_name(),
        structs = struct_declarations(case),
        root = wgsl_type(&case.root()),
        reads = reads(case),
    )
}

fn write_project(dir: &Path, cases: &[&Case]) {
    std::fs::create_dir_all(dir).expect("project folder");
    let names: Vec<String> = cases.iter().map(|c| format!("{:?}", c.shader_name())).collect();
    std::fs::write(dir.join("kiln.toml"), format!("always_include = [{}]\n", names.join(", ")))
        .expect("kiln.toml");
    for case in cases {
        std::fs::write(dir.join(format!("Case{}.shader", case.index)), shader(case)).expect("shader");
    }
}

// ---------------------------------------------------------------------------------------------
// Reading the outputs back.

/// A name as the source had it: naga's writer appends `_` to names that end in a digit.
fn source_name(name: &str) -> String {
    match name.strip_suffix('_') {
        Some(stem) if stem.ends_with(|c: char| c.is_ascii_digit()) => stem.to_string(),
        _ => name.to_string(),
    }
}

/// The WGSL kiln wrote, its struct declarations parsed into the model.
fn parse_wgsl_structs(text: &str) -> Structs {
    let mut structs = Structs::new();
    let mut current: Option<StructDef> = None;
    for line in text.lines() {
        let line = line.trim();
        if let Some(rest) = line.strip_prefix("struct ") {
            let name = source_name(rest.trim_end_matches('{').trim());
            current = Some(StructDef { name, members: Vec::new() });
        } else if line == "}" {
            if let Some(def) = current.take() {
                structs.insert(def.name.clone(), def);
            }
        } else if let Some(def) = current.as_mut() {
            let mut rest = line.trim_end_matches(',');
            let (mut align, mut size) = (None, None);
            while let Some(attribute) = rest.strip_prefix('@') {
                let (head, tail) = attribute.split_once(')').expect("attribute with a value");
                let (name, value) = head.split_once('(').expect("attribute value");
                let value: u32 = value.parse().expect("integer attribute");
                match name {
                    "align" => align = Some(value),
                    "size" => size = Some(value),
                    other => panic!("unexpected attribute {other}"),
                }
                rest = tail.trim_start();
            }
            let (name, ty) = rest.split_once(':').expect("member");
            def.members.push(MemberDef {
                name: source_name(name.trim()),
                ty: parse_type(ty.trim()),
                align,
                size,
            });
        }
    }
    structs
}

fn parse_type(text: &str) -> Ty {
    let scalar = |s: &str| -> &'static str {
        match s {
            "f32" => "f32",
            "i32" => "i32",
            "u32" => "u32",
            "f16" => "f16",
            other => panic!("scalar {other}"),
        }
    };
    if let Some(inner) = text.strip_prefix("array<").and_then(|t| t.strip_suffix('>')) {
        return match inner.rsplit_once(',') {
            Some((element, n)) if n.trim().parse::<u32>().is_ok() => {
                Ty::Array(Box::new(parse_type(element.trim())), Some(n.trim().parse().expect("length")))
            }
            _ => Ty::Array(Box::new(parse_type(inner.trim())), None),
        };
    }
    if let Some(rest) = text.strip_prefix("vec") {
        let (n, s) = rest.split_once('<').expect("vector");
        return Ty::Vector(n.parse().expect("size"), scalar(s.trim_end_matches('>')));
    }
    if let Some(rest) = text.strip_prefix("mat") {
        let (shape, s) = rest.split_once('<').expect("matrix");
        let (c, r) = shape.split_once('x').expect("shape");
        return Ty::Matrix(
            c.parse().expect("columns"),
            r.parse().expect("rows"),
            scalar(s.trim_end_matches('>')),
        );
    }
    match text {
        "f32" | "i32" | "u32" | "f16" => Ty::Scalar(scalar(text)),
        name => Ty::Struct(source_name(name)),
    }
}

/// The parts of a SPIR-V module that say where things are.
#[derive(Default)]
struct Spirv {
    /// Struct id → member type ids.
    structs: BTreeMap<u32, Vec<u32>>,
    /// Array id → (element id, runtime-sized).
    arrays: BTreeMap<u32, u32>,
    matrices: BTreeMap<u32, u32>,
    member_offsets: BTreeMap<(u32, u32), u32>,
    matrix_strides: BTreeMap<(u32, u32), u32>,
    array_strides: BTreeMap<u32, u32>,
    pointers: BTreeMap<u32, u32>,
    /// The uniform or storage buffer variable's pointee type.
    block: Option<u32>,
}

fn parse_spirv(bytes: &[u8]) -> Spirv {
    let words: Vec<u32> =
        bytes.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
    let mut spirv = Spirv::default();
    let mut at = 5;
    let mut buffer_pointer = None;
    while at < words.len() {
        let (count, opcode) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        let operands = &words[at + 1..at + count.max(1)];
        match opcode {
            24 => {
                spirv.matrices.insert(operands[0], operands[1]);
            }
            28 | 29 => {
                spirv.arrays.insert(operands[0], operands[1]);
            }
            30 => {
                spirv.structs.insert(operands[0], operands[1..].to_vec());
            }
            32 => {
                spirv.pointers.insert(operands[0], operands[2]);
            }
            // OpVariable in the Uniform (2) or StorageBuffer (12) storage class.
            59 if operands[2] == 2 || operands[2] == 12 => buffer_pointer = Some(operands[0]),
            71 if operands[1] == 6 => {
                spirv.array_strides.insert(operands[0], operands[2]);
            }
            72 if operands[2] == 35 => {
                spirv.member_offsets.insert((operands[0], operands[1]), operands[3]);
            }
            72 if operands[2] == 7 => {
                spirv.matrix_strides.insert((operands[0], operands[1]), operands[3]);
            }
            _ => {}
        }
        at += count.max(1);
    }
    spirv.block = buffer_pointer.and_then(|p| spirv.pointers.get(&p).copied());
    spirv
}

/// Compares a SPIR-V type with the reference's: member offsets, array and matrix strides. In a
/// uniform buffer naga writes a two-row matrix as its columns (std140), which is checked too.
fn compare_spirv(
    ty: &Ty,
    id: u32,
    spirv: &Spirv,
    structs: &Structs,
    uniform: bool,
    at: &str,
) -> Result<(), String> {
    match ty {
        Ty::Struct(name) => {
            let def = &structs[name];
            let members = spirv.structs.get(&id).ok_or(format!("{at}: not a struct in SPIR-V"))?;
            let mut j = 0u32;
            for (member, offset) in def.members.iter().zip(offsets(def, structs)) {
                let here = format!("{at}.{}", member.name);
                let found = |j: u32| spirv.member_offsets.get(&(id, j)).copied();
                match &member.ty {
                    Ty::Matrix(columns, 2, s) if uniform => {
                        let stride = stride_of(&Ty::Vector(2, s), structs);
                        for c in 0..*columns {
                            if found(j) != Some(offset + c * stride) {
                                return Err(format!(
                                    "{here} column {c}: SPIR-V offset {:?}, spec {}",
                                    found(j),
                                    offset + c * stride
                                ));
                            }
                            j += 1;
                        }
                        continue;
                    }
                    Ty::Matrix(_, rows, s) => {
                        let stride = stride_of(&Ty::Vector(*rows, s), structs);
                        let found_stride = spirv.matrix_strides.get(&(id, j)).copied();
                        if found_stride != Some(stride) {
                            return Err(format!(
                                "{here}: SPIR-V MatrixStride {found_stride:?}, spec {stride}"
                            ));
                        }
                    }
                    _ => {}
                }
                if found(j) != Some(offset) {
                    return Err(format!("{here}: SPIR-V offset {:?}, spec {offset}", found(j)));
                }
                let member_id = *members.get(j as usize).ok_or(format!("{here}: missing in SPIR-V"))?;
                compare_spirv(&member.ty, member_id, spirv, structs, uniform, &here)?;
                j += 1;
            }
            Ok(())
        }
        Ty::Array(element, _) => {
            let stride = stride_of(element, structs);
            let found = spirv.array_strides.get(&id).copied();
            if found != Some(stride) {
                return Err(format!("{at}: SPIR-V ArrayStride {found:?}, spec {stride}"));
            }
            let element_id = spirv.arrays[&id];
            match &**element {
                // A two-row matrix as an array element in a uniform buffer: a struct of columns.
                Ty::Matrix(columns, 2, s) if uniform => {
                    let column = stride_of(&Ty::Vector(2, s), structs);
                    for c in 0..*columns {
                        let found = spirv.member_offsets.get(&(element_id, c)).copied();
                        if found != Some(c * column) {
                            return Err(format!(
                                "{at}[] column {c}: SPIR-V offset {found:?}, spec {}",
                                c * column
                            ));
                        }
                    }
                    Ok(())
                }
                Ty::Matrix(_, rows, s) => {
                    // An array's matrix stride sits on the struct member holding the array.
                    let _ = (rows, s);
                    Ok(())
                }
                other => compare_spirv(other, element_id, spirv, structs, uniform, &format!("{at}[]")),
            }
        }
        _ => Ok(()),
    }
}

/// Compares a reflected member list (manifest, `kiln reflect`) with the reference.
fn compare_members(
    members: &[kiln::reflect::Member],
    def: &StructDef,
    structs: &Structs,
    at: &str,
) -> Result<(), String> {
    if members.len() != def.members.len() {
        return Err(format!("{at}: {} members reflected, {} declared", members.len(), def.members.len()));
    }
    for ((found, member), offset) in members.iter().zip(&def.members).zip(offsets(def, structs)) {
        let here = format!("{at}.{}", member.name);
        let runtime = matches!(member.ty, Ty::Array(_, None));
        let expected_size = if runtime { 0 } else { size_of(&member.ty, structs) };
        let expected = (offset, expected_size, align_of(&member.ty, structs));
        let got = (found.offset, found.size, found.alignment);
        if got != expected {
            return Err(format!("{here}: (offset, size, alignment) {got:?}, spec {expected:?}"));
        }
        let mut element = &member.ty;
        if let Ty::Array(inner, length) = &member.ty {
            let stride = stride_of(inner, structs);
            if found.array_stride != Some(stride) || found.array_length != *length {
                return Err(format!(
                    "{here}: stride {:?} length {:?}, spec {stride} {length:?}",
                    found.array_stride, found.array_length
                ));
            }
            element = inner;
        }
        while let Ty::Array(inner, _) = element {
            element = inner;
        }
        if let Ty::Struct(name) = element {
            compare_members(&found.members, &structs[name], structs, &here)?;
        }
    }
    Ok(())
}

/// The structs a type uses, itself included.
fn reachable(ty: &Ty, structs: &Structs) -> std::collections::BTreeSet<String> {
    let mut found = std::collections::BTreeSet::new();
    let mut pending = vec![ty.clone()];
    while let Some(ty) = pending.pop() {
        match ty {
            Ty::Array(element, _) => pending.push(*element),
            Ty::Struct(name) if found.insert(name.clone()) => {
                pending.extend(structs[&name].members.iter().map(|m| m.ty.clone()));
            }
            _ => {}
        }
    }
    found
}

/// The generated Rust's `size_of` and `offset_of!` assertions, by Rust struct name.
fn rust_assertions(text: &str) -> BTreeMap<String, (u32, BTreeMap<String, u32>)> {
    let mut found: BTreeMap<String, (u32, BTreeMap<String, u32>)> = BTreeMap::new();
    for line in text.lines() {
        let line = line.trim();
        if let Some(rest) = line.strip_prefix("const _: () = assert!(::core::mem::size_of::<") {
            let (name, size) = rest.split_once(">() == ").expect("size assertion");
            found.entry(name.to_string()).or_default().0 = size.trim_end_matches(");").parse().expect("size");
        } else if let Some(rest) = line.strip_prefix("const _: () = assert!(::core::mem::offset_of!(") {
            let (args, offset) = rest.split_once(") == ").expect("offset assertion");
            let (name, field) = args.split_once(", ").expect("struct and field");
            let offset = offset.trim_end_matches(");").parse().expect("offset");
            found.entry(name.to_string()).or_default().1.insert(field.to_string(), offset);
        }
    }
    found
}

// ---------------------------------------------------------------------------------------------
// The tests.

const CASES: usize = 520;
const SEED: u64 = 0x6b69_6c6e_2023;

fn cases() -> Vec<Case> {
    let mut rng = Rng(SEED);
    (0..CASES).map(|i| random_case(i, &mut rng)).collect()
}

#[derive(Debug, PartialEq)]
enum Verdict {
    Valid,
    /// The spec forbids it in this address space.
    Invalid(String),
    /// Valid, but naga's SPIR-V writer gets this struct member wrong: kiln ships the module as
    /// WGSL only, with a warning naming it (K0415).
    WgslOnly(String),
}

fn verdict(case: &Case) -> Verdict {
    let structs = case.structs();
    if case.uniform {
        if let Some(why) = uniform_violation(&case.root(), &structs) {
            return Verdict::Invalid(why);
        }
        if let Some(member) = kiln_refusal(&case.root(), &structs, false) {
            return Verdict::WgslOnly(member);
        }
    }
    Verdict::Valid
}

/// Builds `cases` as one project; returns the manifest (when it built) and the diagnostics.
fn build(dir: &Path, cases: &[&Case]) -> (Option<Manifest>, Vec<kiln::diagnostics::Diagnostic>, SourceStore) {
    write_project(&dir.join("project"), cases);
    let mut store = SourceStore::new();
    let output = dir.join("out");
    let mode = Request {
        output: Some(output.clone()),
        unused_shaders: VariantSelection::All { limit: 16 },
        ..Request::default()
    };
    let (result, mut diagnostics) =
        build_project(&mut store, &[dir.join("project")], &mode, &|_, _| {}).expect("project");
    diagnostics.extend(result.diagnostics);
    (Manifest::read(&output).ok(), diagnostics, store)
}

/// [`build`] of cases that must build: the manifest, or the diagnostics as the failure.
fn build_valid(dir: &Path, cases: &[&Case]) -> Manifest {
    let (manifest, diagnostics, store) = build(dir, cases);
    assert!(
        !kiln::diagnostics::has_errors(&diagnostics),
        "{}",
        kiln::diagnostics::render_plain(&store, &diagnostics)
    );
    manifest.expect("manifest")
}

#[test]
fn the_reference_gives_the_spec_examples_numbers() {
    for (case, expected) in spec_examples() {
        let structs = case.structs();
        for (name, offsets_expected, size, align) in expected {
            let def = &structs[name];
            assert_eq!(offsets(def, &structs), offsets_expected, "{name}");
            let ty = Ty::Struct(name.to_string());
            assert_eq!((size_of(&ty, &structs), align_of(&ty, &structs)), (size, align), "{name}");
        }
    }
}

#[test]
fn every_output_lays_random_structs_out_as_the_wgsl_spec_does() {
    let spirv_val =
        tool("spirv-val", "spirv-tools", "every_output_lays_random_structs_out_as_the_wgsl_spec_does");
    let mut all = cases();
    all.extend(spec_examples().into_iter().map(|(case, _)| case));
    let verdicts: Vec<Verdict> = all.iter().map(verdict).collect();
    let valid: Vec<&Case> =
        all.iter().zip(&verdicts).filter(|(_, v)| **v == Verdict::Valid).map(|(c, _)| c).collect();
    let dir = tempfile::tempdir().expect("temp dir");

    let (manifest, diagnostics, store) = build(&dir.path().join("valid"), &valid);
    let rendered = kiln::diagnostics::render_plain(&store, &diagnostics);
    assert!(
        !kiln::diagnostics::has_errors(&diagnostics),
        "kiln refuses structs the spec allows:\n{rendered}"
    );
    let manifest = manifest.expect("manifest");
    let output = dir.path().join("valid/out");
    let rust = kiln::codegen::generate(&manifest, "out").expect("names do not clash");
    let assertions = rust_assertions(&rust);

    let mut counts: BTreeMap<&str, (usize, usize)> = BTreeMap::new();
    let mut failures = Vec::new();
    let mut check = |output: &'static str, result: Result<(), String>| {
        let entry = counts.entry(output).or_default();
        entry.0 += 1;
        if let Err(why) = result {
            entry.1 += 1;
            failures.push(format!("{output}: {why}"));
        }
    };
    let mut structs_checked = 0;
    let mut constructs: BTreeMap<&str, usize> = BTreeMap::new();
    let scratch = tempfile::tempdir().expect("temp dir");
    for case in &valid {
        // Only what the block uses is in the modules.
        let structs = case.structs();
        let structs: Structs =
            reachable(&case.root(), &structs).into_iter().map(|n| (n.clone(), structs[&n].clone())).collect();
        structs_checked += structs.len();
        for def in structs.values() {
            for member in &def.members {
                let mut ty = &member.ty;
                *constructs
                    .entry(if member.align.is_some() { "@align" } else { "no @align" })
                    .or_default() += 1;
                if member.size.is_some() {
                    *constructs.entry("@size").or_default() += 1;
                }
                let mut depth = 0;
                while let Ty::Array(inner, length) = ty {
                    *constructs
                        .entry(if length.is_none() { "runtime-sized array" } else { "array" })
                        .or_default() += 1;
                    depth += 1;
                    ty = inner;
                }
                if depth > 1 {
                    *constructs.entry("array of arrays").or_default() += 1;
                }
                *constructs
                    .entry(match ty {
                        Ty::Scalar("f16") | Ty::Vector(_, "f16") | Ty::Matrix(_, _, "f16") => "f16",
                        Ty::Matrix(..) => "matrix",
                        Ty::Vector(3, _) => "vec3",
                        Ty::Struct(_) => "nested struct",
                        _ => "scalar or vec2/vec4",
                    })
                    .or_default() += 1;
            }
        }
        let name = case.shader_name();
        let Some(shader) = manifest.shaders.iter().find(|s| s.name == name) else {
            check("manifest", Err(format!("{name}: not in the manifest")));
            continue;
        };
        let pass = &shader.passes[0];
        let root = &case.structs.last().expect("root").name;
        let root_ty = case.root();
        // The manifest.
        let block = pass.uniform_blocks.iter().find(|b| b.name == "blk");
        check(
            "manifest",
            match block {
                None => Err(format!("{name}: no block")),
                Some(block) => {
                    let mut fixed = size_of(&root_ty, &structs);
                    if let Some(MemberDef { ty: Ty::Array(_, None), .. }) = structs[root].members.last() {
                        fixed = *offsets(&structs[root], &structs).last().expect("members");
                    }
                    let got = (block.size, block.alignment);
                    let expected = (fixed, align_of(&root_ty, &structs));
                    if got != expected {
                        Err(format!("{name}: block (size, alignment) {got:?}, spec {expected:?}"))
                    } else {
                        compare_members(&block.members, &structs[root], &structs, &name)
                    }
                }
            },
        );
        // `kiln reflect` (one case in ten: it compiles the variant again).
        if case.index % 10 == 0 {
            let request = kiln::project::VariantRequest {
                shader: dir.path().join(format!("valid/project/Case{}.shader", case.index)),
                pass: None,
                keywords: Vec::new(),
                stage: kiln::preprocess::Stage::Fragment,
                project: None,
            };
            let (json, _) =
                kiln::project::reflect_variant(&mut SourceStore::new(), &request).expect("reflect");
            let blocks: Vec<kiln::reflect::UniformBlock> = json
                .and_then(|j| serde_json::from_value(j["uniform_blocks"].clone()).ok())
                .unwrap_or_default();
            check(
                "kiln reflect",
                match blocks.iter().find(|b| b.name == "blk") {
                    None => Err(format!("{name}: `kiln reflect` gives no block")),
                    Some(block) => compare_members(&block.members, &structs[root], &structs, &name),
                },
            );
        }
        // The generated Rust, struct by struct (names as WGSL's; layouts named once).
        for def in structs.values() {
            let Some((size, fields)) = assertions.get(&def.name) else { continue };
            let ty = Ty::Struct(def.name.clone());
            let mut result = Ok(());
            let runtime = matches!(def.members.last(), Some(MemberDef { ty: Ty::Array(_, None), .. }));
            let expected_size = if runtime {
                *offsets(def, &structs).last().expect("members")
            } else {
                size_of(&ty, &structs)
            };
            if *size != expected_size {
                result = Err(format!("{}: Rust size {size}, spec {expected_size}", def.name));
            }
            for (member, offset) in def.members.iter().zip(offsets(def, &structs)) {
                let field = member.name.clone();
                if let Some(found) = fields.get(&field)
                    && *found != offset
                {
                    result = Err(format!("{}.{field}: Rust offset {found}, spec {offset}", def.name));
                }
            }
            check("generated Rust", result);
        }
        // The modules: the stage that reads the block.
        let Some(stage) =
            (0..pass.modules.len()).map(|m| pass.stage(m)).find(|s| !s.interface.uniform_blocks.is_empty())
        else {
            check("manifest", Err(format!("{name}: no stage uses the block")));
            continue;
        };
        let wgsl =
            String::from_utf8(stage.wgsl().expect("wgsl").read(&output).expect("module")).expect("UTF-8");
        let written = parse_wgsl_structs(&wgsl);
        check(
            "WGSL written",
            structs.values().try_for_each(|def| {
                let Some(out) = written.get(&def.name) else { return Err(format!("{}: not in the WGSL", def.name)) };
                let (a, b) = (offsets(def, &structs), offsets(out, &written));
                let (ty, out_ty) = (Ty::Struct(def.name.clone()), Ty::Struct(out.name.clone()));
                let sizes = (size_of(&ty, &structs), align_of(&ty, &structs));
                let out_sizes = (size_of(&out_ty, &written), align_of(&out_ty, &written));
                if a != b || sizes != out_sizes {
                    Err(format!("{name}: {} is laid out {b:?} {out_sizes:?} in kiln's WGSL, {a:?} {sizes:?} in the source", def.name))
                } else {
                    Ok(())
                }
            }),
        );
        // naga reading kiln's WGSL again, as a consumer does.
        check(
            "naga reading kiln's WGSL",
            match naga::front::wgsl::parse_str(&wgsl) {
                Err(error) => Err(format!("{name}: {}", error.emit_to_string(&wgsl))),
                Ok(module) => structs.values().try_for_each(|def| {
                    let found = module.types.iter().find(|(_, t)| {
                        t.name.as_deref().map(source_name).as_deref() == Some(def.name.as_str())
                    });
                    match found.map(|(_, t)| &t.inner) {
                        Some(naga::TypeInner::Struct { members, span }) => {
                            let got: Vec<u32> = members.iter().map(|m| m.offset).collect();
                            let expected = offsets(def, &structs);
                            let runtime =
                                matches!(def.members.last(), Some(MemberDef { ty: Ty::Array(_, None), .. }));
                            let size_ok =
                                runtime || *span == size_of(&Ty::Struct(def.name.clone()), &structs);
                            if got != expected || !size_ok {
                                Err(format!(
                                    "{name}: naga reads {} as {got:?} (span {span}), spec {expected:?}",
                                    def.name
                                ))
                            } else {
                                Ok(())
                            }
                        }
                        _ => Err(format!("{name}: {} missing", def.name)),
                    }
                }),
            },
        );
        // SPIR-V decorations, and spirv-val.
        let spirv_bytes = stage.spirv().expect("spirv").read(&output).expect("module");
        let spirv = parse_spirv(&spirv_bytes);
        check(
            "SPIR-V decorations",
            match spirv.block {
                None => Err(format!("{name}: no buffer variable in SPIR-V")),
                Some(block) => {
                    // naga wraps a block in a struct of one member, unless it ends in a
                    // runtime-sized array.
                    let runtime = matches!(
                        structs[root].members.last(),
                        Some(MemberDef { ty: Ty::Array(_, None), .. })
                    );
                    let wrapped = spirv.structs.get(&block).and_then(|m| m.first()).copied();
                    let id = if runtime { Some(block) } else { wrapped };
                    match id {
                        Some(id) => compare_spirv(&root_ty, id, &spirv, &structs, case.uniform, &name),
                        None => Err(format!("{name}: the block's wrapper is not a struct")),
                    }
                }
            },
        );
        if spirv_val {
            let path = scratch.path().join(format!("{}.spv", case.index));
            std::fs::write(&path, &spirv_bytes).expect("write");
            let environment =
                if spirv_bytes[6] == 1 && spirv_bytes[5] == 0 { "vulkan1.0" } else { "vulkan1.1" };
            let run = std::process::Command::new("spirv-val")
                .args(["--target-env", environment])
                .arg(&path)
                .output()
                .expect("spirv-val runs");
            check(
                "spirv-val",
                if run.status.success() {
                    Ok(())
                } else {
                    Err(format!(
                        "{name}: {}",
                        String::from_utf8_lossy(&run.stderr) + String::from_utf8_lossy(&run.stdout)
                    ))
                },
            );
        }
    }
    println!("{} cases, {structs_checked} structs built; members by construct: {constructs:?}", valid.len());
    println!("agreement per output (checked, disagreeing): {counts:?}");
    assert!(failures.is_empty(), "{} disagreements:\n{}", failures.len(), failures.join("\n"));
    assert!(structs_checked >= 500, "only {structs_checked} structs");
}

/// The generated Rust of a quarter of the cases, compiled by cargo: rustc evaluates its `const`
/// size and offset assertions on the real `#[repr(C)]` layouts (and the offsets asserted are
/// the spec's, checked above), so a struct the renderer fills has the WGSL layout.
#[test]
fn the_generated_rust_of_random_structs_compiles_with_its_layout_assertions() {
    let all = cases();
    let sample: Vec<&Case> = all.iter().filter(|c| verdict(c) == Verdict::Valid).step_by(4).collect();
    let dir = tempfile::tempdir().expect("temp dir");
    let manifest = build_valid(dir.path(), &sample);
    let krate = dir.path().join("crate");
    let module = kiln::codegen::generate(&manifest, "out").expect("names do not clash");
    crate::support::generated_module_crate(
        &krate,
        &module,
        (&dir.path().join("out"), "out"),
        "#![allow(dead_code, non_snake_case, non_camel_case_types, clippy::all)]\npub mod shaders;\n",
    );
    let run = crate::support::cargo_scratch(&krate, &["build"]);
    assert!(
        run.status.success(),
        "the generated Rust does not compile:\n{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let assertions = module.matches("const _: () = assert!(::core::mem::").count();
    println!("{} cases' generated Rust compiled: {assertions} size and offset assertions hold", sample.len());
    assert!(assertions > 500, "{assertions}");
}

#[test]
fn structs_the_spec_forbids_are_refused_and_those_naga_cannot_write_warn() {
    let all = cases();
    let refused: Vec<(&Case, Verdict)> =
        all.iter().map(|c| (c, verdict(c))).filter(|(_, v)| *v != Verdict::Valid).collect();
    let invalid = refused.iter().filter(|(_, v)| matches!(v, Verdict::Invalid(_))).count();
    let wgsl_only = refused.len() - invalid;
    println!("{invalid} cases the spec forbids, {wgsl_only} kiln ships as WGSL only (K0415)");
    assert!(invalid >= 20 && wgsl_only >= 5, "too few generated: {invalid}, {wgsl_only}");
    let dir = tempfile::tempdir().expect("temp dir");
    // Apart: a build with errors writes nothing, and the WGSL-only modules are to be looked at.
    let of = |wgsl_only: bool| -> Vec<&Case> {
        refused
            .iter()
            .filter(|(_, v)| matches!(v, Verdict::WgslOnly(_)) == wgsl_only)
            .map(|(c, _)| *c)
            .collect()
    };
    let (_, errors, store) = build(&dir.path().join("invalid"), &of(false));
    let (manifest, warnings, wgsl_store) = build(&dir.path().join("wgsl-only"), &of(true));
    let mut failures = Vec::new();
    for (case, verdict) in &refused {
        let (diagnostics, store) = if matches!(verdict, Verdict::WgslOnly(_)) {
            (&warnings, &wgsl_store)
        } else {
            (&errors, &store)
        };
        let file = format!("Case{}.shader", case.index);
        let at_case: Vec<&kiln::diagnostics::Diagnostic> = diagnostics
            .iter()
            .filter(|d| {
                d.primary.as_ref().and_then(|p| store.path(p.span.file)).is_some_and(|p| p.ends_with(&file))
            })
            .collect();
        let rendered =
            kiln::diagnostics::render_plain(store, &at_case.iter().map(|d| (*d).clone()).collect::<Vec<_>>());
        match verdict {
            Verdict::Invalid(why) => {
                if !at_case.iter().any(|d| d.code == "K0402") {
                    failures.push(format!("{file} ({why}) is not refused:\n{rendered}"));
                }
            }
            Verdict::WgslOnly(member) => {
                let warned = at_case.iter().any(|d| {
                    d.code == "K0415"
                        && d.severity == kiln::diagnostics::Severity::Warning
                        && d.message.contains(&format!("`{member}`"))
                });
                if !warned || at_case.iter().any(|d| d.severity == kiln::diagnostics::Severity::Error) {
                    failures.push(format!("{file}: `{member}` does not warn with K0415 alone:\n{rendered}"));
                }
                let all_spirv = manifest.as_ref().and_then(|m| {
                    let shader = m.shaders.iter().find(|s| s.name == case.shader_name())?;
                    Some(shader.passes[0].modules.iter().all(|module| module.spirv.is_some()))
                });
                if all_spirv != Some(false) {
                    failures
                        .push(format!("{file}: every module has SPIR-V ({all_spirv:?}), or none was built"));
                }
            }
            Verdict::Valid => unreachable!(),
        }
    }
    assert!(failures.is_empty(), "{} cases:\n{}", failures.len(), failures.join("\n"));
}

/// A sample of blocks filled on the host at the reference's offsets, read back scalar by scalar
/// on the GPU through the struct declarations of kiln's WGSL.
#[test]
fn the_gpu_reads_every_scalar_where_the_spec_puts_it() {
    let Some(gpu) = gpu("the_gpu_reads_every_scalar_where_the_spec_puts_it") else { return };
    reads_every_scalar_where_the_spec_puts_it(&gpu, false);
}

/// The same on wgpu's OpenGL back end, where naga's GLSL lays the blocks out (std140, std430):
/// every block kiln refuses for GL (K0422, a member `@size` or `@align` moves) reads wrong there,
/// and every other block reads right.
#[test]
fn wgpu_s_gl_back_end_reads_every_scalar_where_the_spec_puts_it() {
    let Some(gpu) = crate::support::gl_gpu("wgpu_s_gl_back_end_reads_every_scalar_where_the_spec_puts_it")
    else {
        return;
    };
    reads_every_scalar_where_the_spec_puts_it(&gpu, true);
}

/// The sample's cases kiln refuses for GLSL because GLSL would lay their block out elsewhere.
fn refused_for_gl(dir: &Path, sample: &[&Case]) -> Vec<String> {
    let mut store = SourceStore::new();
    let mode = Request {
        write: false,
        backends: vec![kiln::manifest::Backend::Glsl],
        unused_shaders: VariantSelection::All { limit: 16 },
        ..Request::default()
    };
    let (result, mut diagnostics) =
        build_project(&mut store, &[dir.join("project")], &mode, &|_, _| {}).expect("project");
    diagnostics.extend(result.diagnostics);
    let shown: Vec<String> = diagnostics
        .iter()
        .filter(|d| d.code == "K0422" && d.message.contains("GL back end reads it from the wrong bytes"))
        .map(|d| kiln::diagnostics::render_plain(&store, std::slice::from_ref(d)))
        .collect();
    sample
        .iter()
        .map(|c| c.shader_name())
        .filter(|name| shown.iter().any(|d| d.contains(&format!("`{name}`"))))
        .collect()
}

fn reads_every_scalar_where_the_spec_puts_it(gpu: &kiln::accuracy::gpu::Gpu, gl: bool) {
    let has_f16 = gpu.device.features().contains(wgpu::Features::SHADER_F16);
    let all = cases();
    let sample: Vec<&Case> = all
        .iter()
        .filter(|c| verdict(c) == Verdict::Valid && (has_f16 || !c.half))
        .step_by(7)
        .take(28)
        .collect();
    assert!(sample.len() >= 20, "{} cases", sample.len());
    let dir = tempfile::tempdir().expect("temp dir");
    let manifest = build_valid(dir.path(), &sample);
    let refused = if gl { refused_for_gl(dir.path(), &sample) } else { Vec::new() };
    let output = dir.path().join("out");
    let (mut scalars, mut wrong_where_refused) = (0, 0);
    for case in &sample {
        let shader = manifest.shaders.iter().find(|s| s.name == case.shader_name()).expect("shader");
        let pass = &shader.passes[0];
        let stage = (0..pass.modules.len())
            .map(|m| pass.stage(m))
            .find(|s| !s.interface.uniform_blocks.is_empty())
            .expect("stage");
        let wgsl =
            String::from_utf8(stage.wgsl().expect("wgsl").read(&output).expect("module")).expect("UTF-8");
        // kiln's struct declarations, with a compute entry point that copies every scalar out.
        let mut declarations = String::new();
        let mut inside = false;
        for line in wgsl.lines() {
            if line.starts_with("enable ") || line.starts_with("struct ") {
                inside = line.starts_with("struct ");
                declarations.push_str(line);
                declarations.push('\n');
            } else if inside {
                declarations.push_str(line);
                declarations.push('\n');
                inside = line != "}";
            }
        }
        let structs = case.structs();
        let mut found = Vec::new();
        leaves(&case.root(), "blk", 0, &structs, &mut found);
        let space = if case.uniform { "uniform" } else { "storage, read" };
        let mut program = format!(
            "{declarations}\n@group(0) @binding(0) var<{space}> blk: {};\n@group(0) @binding(1) var<storage, read_write> copied: array<u32>;\n@compute @workgroup_size(1) fn main() {{\n",
            wgsl_type(&case.root())
        );
        for (i, (path, _, scalar)) in found.iter().enumerate() {
            let value = match *scalar {
                "f32" | "i32" => format!("bitcast<u32>({path})"),
                "f16" => format!("pack2x16float(vec2<f32>(f32({path}), 0.0))"),
                _ => path.clone(),
            };
            let _ = writeln!(program, "    copied[{i}] = {value};");
        }
        program.push_str("}\n");
        // The block's bytes: scalar k holds k + 1 (as its type), everything else 0xAB.
        let end = found.iter().map(|(_, offset, s)| offset + width(s)).max().unwrap_or(0);
        // Room past the last scalar: a runtime-sized array's binding must hold a whole element.
        let end = end.max(size_of(&case.root(), &structs)) + 256;
        let mut bytes = vec![0xABu8; round_up(256, end) as usize];
        let mut expected = Vec::new();
        for (k, (_, offset, scalar)) in found.iter().enumerate() {
            let n = k as u32 + 1;
            let (written, copied): (Vec<u8>, u32) = match *scalar {
                "f32" => ((n as f32).to_le_bytes().to_vec(), (n as f32).to_bits()),
                "i32" => ((-(n as i32)).to_le_bytes().to_vec(), (-(n as i32)) as u32),
                "f16" => {
                    let half = f16_bits(n as f32);
                    (half.to_le_bytes().to_vec(), u32::from(half))
                }
                _ => (n.to_le_bytes().to_vec(), n),
            };
            let at = *offset as usize;
            bytes[at..at + written.len()].copy_from_slice(&written);
            expected.push(copied);
        }
        let got = copy_scalars(gpu, &program, case.uniform, &bytes, found.len());
        match got {
            Err(error) => panic!("{}: {error}\n{program}", case.shader_name()),
            Ok(got) => {
                let wrong: Vec<String> = found
                    .iter()
                    .zip(expected.iter().zip(&got))
                    .filter(|(_, (e, g))| e != g)
                    .map(|((path, offset, s), (e, g))| {
                        format!("{path} ({s} at {offset}): expected {e:#x}, read {g:#x}")
                    })
                    .collect();
                if refused.contains(&case.shader_name()) {
                    assert!(
                        !wrong.is_empty(),
                        "{} is refused for GL but reads right there",
                        case.shader_name()
                    );
                    wrong_where_refused += 1;
                    continue;
                }
                assert!(wrong.is_empty(), "{}:\n{}\n{program}", case.shader_name(), wrong.join("\n"));
            }
        }
        scalars += found.len();
    }
    assert_eq!(wrong_where_refused, refused.len());
    println!(
        "{} blocks, {scalars} scalars read back where the spec puts them; {} blocks refused for GL (K0422), each read wrong there",
        sample.len() - refused.len(),
        refused.len()
    );
}

/// An f32 holding a small integer as IEEE half-precision bits.
fn f16_bits(value: f32) -> u16 {
    let bits = value.to_bits();
    let sign = ((bits >> 16) & 0x8000) as u16;
    let exponent = ((bits >> 23) & 0xff) as i32 - 127 + 15;
    let mantissa = ((bits >> 13) & 0x3ff) as u16;
    assert!((1..31).contains(&exponent), "{value} is not a normal f16");
    sign | ((exponent as u16) << 10) | mantissa
}

/// Runs `program` (`blk` at group 0 binding 0, `copied` at binding 1) once with `bytes` as the
/// block, returning the first `count` words it copied; a shader or validation error as text.
fn copy_scalars(
    gpu: &kiln::accuracy::gpu::Gpu,
    program: &str,
    uniform: bool,
    bytes: &[u8],
    count: usize,
) -> Result<Vec<u32>, String> {
    use wgpu::util::DeviceExt;
    let device = &gpu.device;
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: None,
        source: wgpu::ShaderSource::Wgsl(program.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: None,
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let usage = if uniform { wgpu::BufferUsages::UNIFORM } else { wgpu::BufferUsages::STORAGE };
    let block =
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor { label: None, contents: bytes, usage });
    let size = (count.max(1) * 4) as u64;
    let copied = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: block.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 1, resource: copied.as_entire_binding() },
        ],
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }
    encoder.copy_buffer_to_buffer(&copied, 0, &readback, 0, size);
    gpu.queue.submit([encoder.finish()]);
    if let Some(error) = pollster::block_on(scope.pop()) {
        return Err(error.to_string());
    }
    readback.map_async(wgpu::MapMode::Read, .., |_| {});
    let _ = device.poll(wgpu::PollType::wait_indefinitely());
    let words = readback
        .get_mapped_range(..)
        .map_err(|e| e.to_string())?
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    Ok(words)
}
