//! Host-shareable memory layout as the WGSL spec defines it, made true in every output.
//!
//! naga's WGSL front end places a member by its `@align`, but a struct's alignment in naga is
//! the largest of its members' *types'* alignments, so a struct raised by `@align` is placed too
//! early when nested or used as an array element (gfx-rs/wgpu#4377); and naga's WGSL writer drops
//! `@align` and `@size`. kiln reads the attributes from the text ([`scan_structs`]), lays every
//! struct out by the spec and rewrites naga's offsets, spans and strides before anything else
//! sees the module ([`correct`]), and writes the attributes back into the WGSL it emits
//! ([`annotate_wgsl`]).

use super::Mapper;
use crate::diagnostics::Diagnostic;
use crate::preprocess::{Kind, lex};
use naga::{ArraySize, Handle, Module, Type, TypeInner};
use std::collections::HashMap;
use std::ops::Range;

/// The spec's layout of each struct of a module, by name: what naga's IR cannot hold (a
/// struct's alignment, each member's `@align`/`@size`), for reflection and the WGSL writer.
#[derive(Debug, Clone, Default, PartialEq)]
pub(super) struct HostLayout {
    structs: HashMap<String, StructLayout>,
}

#[derive(Debug, Clone, PartialEq)]
struct StructLayout {
    alignment: u32,
    /// Each member's alignment and size in the struct: its `@align`/`@size`, else its type's.
    members: Vec<(u32, u32)>,
}

/// A type's size and alignment by the spec's rules.
#[derive(Debug, Clone, Copy, PartialEq)]
struct TypeLayout {
    size: u32,
    alignment: u32,
}

impl TypeLayout {
    /// The stride of an array of this type (and of a matrix's columns).
    fn stride(self) -> u32 {
        u32::try_from(round_up(self.alignment, u64::from(self.size))).unwrap_or(u32::MAX)
    }
}

impl HostLayout {
    /// The spec's alignment of a type (naga's `Layouter` gives a struct the largest alignment of
    /// its members' types, ignoring `@align`).
    pub(super) fn alignment(&self, module: &Module, ty: Handle<Type>) -> u32 {
        match &module.types[ty].inner {
            TypeInner::Struct { members, .. } => {
                let name = module.types[ty].name.as_deref().unwrap_or_default();
                match self.structs.get(name) {
                    Some(layout) => layout.alignment,
                    None => members.iter().map(|m| self.alignment(module, m.ty)).max().unwrap_or(1),
                }
            }
            TypeInner::Array { base, .. } => self.alignment(module, *base),
            inner => plain_layout(inner, &[]).map_or(1, |layout| layout.alignment),
        }
    }
}

/// A struct declaration as written.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct DeclaredStruct {
    pub name: String,
    pub members: Vec<DeclaredMember>,
}

#[derive(Debug, Clone, PartialEq)]
pub(super) struct DeclaredMember {
    pub name: String,
    pub range: Range<usize>,
    pub align: Option<LayoutAttribute>,
    pub size: Option<LayoutAttribute>,
}

/// An `@align(...)` or `@size(...)`, with its value when it is an integer literal or a named
/// constant (naga evaluated it too; kiln needs it because naga's IR keeps only its effect).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct LayoutAttribute {
    /// Its argument (`2 * 16`).
    pub expression: String,
    /// The whole attribute (`@align(2 * 16)`) in the text.
    pub range: Range<usize>,
}

/// Every `struct` declaration of a text, with its members' `@align` and `@size`.
pub(super) fn scan_structs(text: &str) -> Vec<DeclaredStruct> {
    // The preprocessor's lexer: WGSL's comments, identifiers and numbers are C's.
    let lexed = lex(text);
    let tokens: Vec<(&str, usize)> = lexed.iter().map(|t| (t.text.as_ref(), t.at)).collect();
    let mut structs = Vec::new();
    let mut i = 0;
    while i + 2 < tokens.len() {
        let name = tokens[i + 1].0;
        if tokens[i].0 != "struct" || lexed[i + 1].kind != Kind::Ident || tokens[i + 2].0 != "{" {
            i += 1;
            continue;
        }
        i += 3;
        let mut members = Vec::new();
        while i < tokens.len() && tokens[i].0 != "}" {
            let mut member = DeclaredMember { name: String::new(), range: 0..0, align: None, size: None };
            while i + 1 < tokens.len() && tokens[i].0 == "@" {
                let attribute = tokens[i + 1].0;
                let start = tokens[i].1;
                i += 2;
                // The text between the parentheses, as written.
                let mut inside = start..start;
                if tokens.get(i).is_some_and(|t| t.0 == "(") {
                    inside = tokens[i].1 + 1..tokens[i].1 + 1;
                    let mut depth = 0;
                    while let Some(&(token, at)) = tokens.get(i) {
                        i += 1;
                        depth += match token {
                            "(" => 1,
                            ")" => -1,
                            _ => 0,
                        };
                        if depth == 0 {
                            inside.end = at;
                            break;
                        }
                    }
                }
                let end = tokens.get(i - 1).map_or(text.len(), |t| t.1 + t.0.len());
                let expression = text[inside].trim().to_string();
                let value = Some(LayoutAttribute { expression, range: start..end });
                match attribute {
                    "align" => member.align = value,
                    "size" => member.size = value,
                    _ => {}
                }
            }
            let Some(&(name, at)) = tokens.get(i) else { break };
            member.name = name.to_string();
            member.range = at..at + name.len();
            // Skip `: type` up to the `,` or `}` that ends the member.
            let mut depth = 0i32;
            while let Some(&(token, _)) = tokens.get(i) {
                match token {
                    "<" | "(" | "[" => depth += 1,
                    ">" | ")" | "]" => depth -= 1,
                    // `array<vec4<f32>>` closes two templates with one C token.
                    ">>" => depth -= 2,
                    "," if depth <= 0 => {
                        i += 1;
                        break;
                    }
                    "}" if depth <= 0 => break,
                    _ => {}
                }
                i += 1;
            }
            members.push(member);
        }
        structs.push(DeclaredStruct { name: name.to_string(), members });
    }
    structs
}

/// An attribute's value: an integer literal, or the name of an integer `const`.
fn attribute_value(module: &Module, attribute: &LayoutAttribute) -> Option<u32> {
    let text = attribute.expression.trim();
    let digits = text.trim_end_matches(['u', 'i']);
    let literal = match digits.strip_prefix("0x").or_else(|| digits.strip_prefix("0X")) {
        Some(hex) => u32::from_str_radix(hex, 16).ok(),
        None => digits.parse().ok(),
    };
    literal.or_else(|| {
        let constant = module.constants.iter().find(|(_, c)| c.name.as_deref() == Some(text))?.1;
        match module.global_expressions[constant.init] {
            naga::Expression::Literal(naga::Literal::U32(v)) => Some(v),
            naga::Expression::Literal(naga::Literal::I32(v)) => u32::try_from(v).ok(),
            naga::Expression::Literal(naga::Literal::AbstractInt(v)) => u32::try_from(v).ok(),
            _ => None,
        }
    })
}

fn round_up(alignment: u32, n: u64) -> u64 {
    let alignment = u64::from(alignment.max(1));
    n.div_ceil(alignment) * alignment
}

/// The spec's size and alignment of a non-struct type whose parts are laid out in `layouts`.
fn plain_layout(inner: &TypeInner, layouts: &[Option<TypeLayout>]) -> Option<TypeLayout> {
    let vector =
        |n: u32, width: u32| TypeLayout { size: n * width, alignment: if n == 3 { 4 } else { n } * width };
    Some(match *inner {
        TypeInner::Scalar(s) | TypeInner::Atomic(s) if s.kind != naga::ScalarKind::Bool => {
            vector(1, u32::from(s.width))
        }
        TypeInner::Vector { size, scalar } if scalar.kind != naga::ScalarKind::Bool => {
            vector(size as u32, u32::from(scalar.width))
        }
        TypeInner::Matrix { columns, rows, scalar } => {
            let column = vector(rows as u32, u32::from(scalar.width));
            TypeLayout { size: columns as u32 * column.stride(), alignment: column.alignment }
        }
        TypeInner::Array { base, size, .. } => {
            let element = layouts[base.index()]?;
            let stride = element.stride();
            let count = match size {
                ArraySize::Constant(n) => n.get(),
                // As naga counts it: a runtime-sized array is as large as one element.
                _ => 1,
            };
            TypeLayout { size: count.checked_mul(stride)?, alignment: element.alignment }
        }
        _ => return None,
    })
}

/// Lays every struct of a freshly parsed module out by the spec, rewriting naga's member
/// offsets, struct spans and array strides where they differ. Refuses (at the struct's
/// file:line) attributes kiln cannot read and `@align` values below the type's alignment.
pub(crate) fn correct(module: &mut Module, text: &str, mapper: &Mapper) -> Result<HostLayout, Diagnostic> {
    // Without `@align` naga lays every struct out as the spec does, and without `@size` too
    // there is nothing to write back: most texts need no more than this look.
    if !has_layout_attribute(text) {
        return Ok(HostLayout::default());
    }
    let declared: HashMap<String, DeclaredStruct> =
        scan_structs(text).into_iter().map(|s| (s.name.clone(), s)).collect();
    let handles: Vec<Handle<Type>> = module.types.iter().map(|(h, _)| h).collect();
    let mut layouts: Vec<Option<TypeLayout>> = vec![None; handles.len()];
    let mut host = HostLayout::default();
    for handle in handles {
        let ty = module.types[handle].clone();
        let (layout, corrected) = match &ty.inner {
            TypeInner::Struct { members, span } => {
                let written = ty.name.as_ref().and_then(|name| declared.get(name)).filter(|d| {
                    d.members.len() == members.len()
                        && d.members
                            .iter()
                            .zip(members)
                            .all(|(d, m)| m.name.as_deref() == Some(d.name.as_str()))
                });
                let Some(placed) = place_members(module, text, members, written, &layouts, mapper)? else {
                    continue;
                };
                let StructPlacement { offsets, members: member_layouts, alignment, size } = placed;
                if let Some(name) = &ty.name {
                    host.structs.insert(name.clone(), StructLayout { alignment, members: member_layouts });
                }
                let mut fixed = members.clone();
                for (member, offset) in fixed.iter_mut().zip(&offsets) {
                    member.offset = *offset;
                }
                let changed = fixed != *members || size != *span;
                let corrected = TypeInner::Struct { members: fixed, span: size };
                (TypeLayout { size, alignment }, changed.then_some(corrected))
            }
            TypeInner::Array { base, size, stride } => {
                let (Some(layout), Some(element)) =
                    (plain_layout(&ty.inner, &layouts), layouts[base.index()])
                else {
                    continue;
                };
                let spec_stride = element.stride();
                let corrected = TypeInner::Array { base: *base, size: *size, stride: spec_stride };
                (layout, (spec_stride != *stride).then_some(corrected))
            }
            inner => match plain_layout(inner, &layouts) {
                Some(layout) => (layout, None),
                None => continue,
            },
        };
        layouts[handle.index()] = Some(layout);
        if let Some(inner) = corrected {
            let replacement = Type { name: ty.name.clone(), inner };
            // `replace` panics when an equal type exists; naga never makes one (its stride and
            // offsets are a function of the same inputs), but a panic here is not an option.
            if module.types.get(&replacement).is_some() {
                return Err(Diagnostic::error(
                    "K0416",
                    format!("internal error: two layouts of type `{}`", ty.name.as_deref().unwrap_or("?")),
                ));
            }
            module.types.replace(handle, replacement);
        }
    }
    Ok(host)
}

/// The layout a module read from SPIR-V already has (HLSL's packing, its offsets decorated), in
/// the form the WGSL writer writes back: each member its type's alignment and, where the next
/// member (or the struct's end) is further on than its own size, an `@size` reaching it.
/// Offsets WGSL cannot give are refused before this ([`super::hlsl`]).
pub(super) fn from_offsets(module: &Module) -> HostLayout {
    let mut layouter = naga::proc::Layouter::default();
    if layouter.update(module.to_ctx()).is_err() {
        return HostLayout::default();
    }
    let mut host = HostLayout::default();
    for (_, ty) in module.types.iter() {
        let (TypeInner::Struct { members, span }, Some(name)) = (&ty.inner, &ty.name) else { continue };
        let alignment = members.iter().map(|m| layouter[m.ty].alignment.round_up(1)).max().unwrap_or(1);
        // Where WGSL would put what follows each member (the next member, or the struct's end).
        let nexts = members.iter().skip(1).map(|m| (m.offset, layouter[m.ty].alignment.round_up(1)));
        let nexts = nexts.chain(std::iter::once((*span, alignment)));
        let placed: Vec<(u32, u32)> = members
            .iter()
            .zip(nexts)
            .map(|(member, (end, next_alignment))| {
                let natural = &layouter[member.ty];
                let own_end = u64::from(member.offset) + u64::from(natural.size);
                let size = if round_up(next_alignment, own_end) == u64::from(end) {
                    natural.size
                } else {
                    end.saturating_sub(member.offset).max(natural.size)
                };
                (natural.alignment.round_up(1), size)
            })
            .collect();
        host.structs.insert(name.clone(), StructLayout { alignment, members: placed });
    }
    host
}

/// A struct whose members' `@size` literals (and 2 bytes for each other member, the least a
/// member takes) add up past 4 GiB, refused before naga parses it: naga sums offsets in 32 bits
/// (they wrap, and its message then says a member "crosses the structure boundary"; a debug
/// build of naga panics). Sums that only types push past are caught after the parse, by
/// [`correct`].
pub(super) fn oversized_struct(text: &str, mapper: &Mapper) -> Option<Diagnostic> {
    if !has_layout_attribute(text) {
        return None;
    }
    for declared in scan_structs(text) {
        let mut end = 0u64;
        for member in &declared.members {
            // A member without `@size` takes at least an `f16`'s 2 bytes.
            let size = member.size.as_ref();
            let literal = size.map(|s| s.expression.trim().trim_end_matches(['u', 'i']));
            end += literal.map_or(2, |l| l.parse::<u64>().unwrap_or(0));
            if end > u64::from(u32::MAX) {
                let range = size.map_or(member.range.clone(), |s| s.range.clone());
                let message = format!(
                    "struct `{}` is larger than 4 GiB: its members take at least {end} bytes by `{}`",
                    declared.name, member.name
                );
                return Some(too_large(mapper, message, Some(range), "past 4 GiB here"));
            }
        }
    }
    None
}

/// Whether the text has an `@align` or `@size` attribute (or the words in a comment).
pub(super) fn has_layout_attribute(text: &str) -> bool {
    text.match_indices('@').any(|(at, _)| {
        let name = text[at + 1..].trim_start();
        name.starts_with("align") || name.starts_with("size")
    })
}

struct StructPlacement {
    offsets: Vec<u32>,
    members: Vec<(u32, u32)>,
    alignment: u32,
    size: u32,
}

/// Places a struct's members by the spec: each at its alignment (its `@align`, else its type's)
/// after the previous member's size (its `@size`, else its type's). `None` when a member's type
/// is not host-shareable (the struct's layout then does not matter).
fn place_members(
    module: &Module,
    text: &str,
    members: &[naga::StructMember],
    written: Option<&DeclaredStruct>,
    layouts: &[Option<TypeLayout>],
    mapper: &Mapper,
) -> Result<Option<StructPlacement>, Diagnostic> {
    let mut placement = StructPlacement { offsets: Vec::new(), members: Vec::new(), alignment: 1, size: 0 };
    let mut end = 0u64;
    let struct_name = written.map_or("", |w| w.name.as_str());
    for (index, member) in members.iter().enumerate() {
        let Some(ty) = layouts[member.ty.index()] else { return Ok(None) };
        let declared = written.map(|w| &w.members[index]);
        let value = |attribute: &Option<LayoutAttribute>| -> Result<Option<u32>, Diagnostic> {
            let Some(attribute) = attribute else { return Ok(None) };
            match attribute_value(module, attribute) {
                Some(v) => Ok(Some(v)),
                None => Err(refusal(
                    mapper,
                    "K0414",
                    format!(
                        "kiln cannot read the value of `{}` on `{struct_name}.{}`",
                        &text[attribute.range.clone()],
                        member.name.as_deref().unwrap_or_default()
                    ),
                    attribute.range.clone(),
                    "not an integer literal or the name of an integer `const`",
                    "write the value, or a `const` holding it (naga's IR keeps only the offsets it gives)",
                )),
            }
        };
        let explicit_align = value(&declared.and_then(|d| d.align.clone()))?;
        let explicit_size = value(&declared.and_then(|d| d.size.clone()))?;
        if let (Some(align), Some(declared)) = (explicit_align, declared)
            && (align < ty.alignment || !align.is_multiple_of(ty.alignment))
        {
            let range = declared.align.as_ref().map_or(declared.range.clone(), |a| a.range.clone());
            return Err(refusal(
                mapper,
                "K0417",
                format!(
                    "`@align({align})` on `{struct_name}.{}` is not a multiple of its type's alignment, {}",
                    declared.name, ty.alignment
                ),
                range,
                "not a multiple of this member's type's alignment",
                &format!(
                    "use `@align({})` or more: a struct's alignment includes its members' `@align`",
                    ty.alignment
                ),
            ));
        }
        let alignment = explicit_align.unwrap_or(ty.alignment);
        let size = explicit_size.unwrap_or(ty.size).max(ty.size);
        // In 64 bits: naga's own sums wrap at 2^32 (a member past the end reads as one that
        // crosses it), and a struct's size is a `u32` everywhere after.
        let offset = round_up(alignment, end);
        let member_end = offset + u64::from(size);
        placement.alignment = placement.alignment.max(alignment);
        let struct_end = round_up(placement.alignment, member_end);
        let (Ok(offset32), Ok(_)) = (u32::try_from(offset), u32::try_from(struct_end)) else {
            let name = member.name.as_deref().unwrap_or_default();
            let message = format!(
                "struct `{struct_name}` is larger than 4 GiB: `{name}` at byte {offset} with size {size} ends at \
                 byte {member_end}"
            );
            let range = declared.map(|d| d.size.as_ref().map_or(d.range.clone(), |a| a.range.clone()));
            return Err(too_large(mapper, message, range, "this member ends past 4 GiB"));
        };
        placement.offsets.push(offset32);
        placement.members.push((alignment, size));
        end = member_end;
    }
    placement.size = u32::try_from(round_up(placement.alignment, end)).unwrap_or(u32::MAX);
    Ok(Some(placement))
}

/// K0425 at `range` (the member's `@size`, else its name), or unplaced where the text's struct
/// was not found.
fn too_large(mapper: &Mapper, message: String, range: Option<Range<usize>>, label: &str) -> Diagnostic {
    let help = "a struct's size must fit in 32 bits; make the member's `@size` (or its array) smaller";
    match range {
        Some(range) => refusal(mapper, "K0425", message, range, label, help),
        None => Diagnostic::error("K0425", message).help(help.to_string()),
    }
}

fn refusal(
    mapper: &Mapper,
    code: &'static str,
    message: String,
    range: Range<usize>,
    label: &str,
    help: &str,
) -> Diagnostic {
    mapper.diagnostic_at(
        Diagnostic::error(code, message).help(help.to_string()),
        vec![(range, label.to_string())],
    )
}

/// The WGSL naga wrote for a module, with `@align`/`@size` written back on every struct member
/// whose layout is not its type's own, so that the text gives the layout the source did (to naga
/// and to a reader that follows the spec).
pub(super) fn annotate_wgsl(wgsl: String, module: &Module, host: &HostLayout) -> Result<String, Diagnostic> {
    if host.structs.is_empty() {
        return Ok(wgsl);
    }
    let mut layouter = naga::proc::Layouter::default();
    if layouter.update(module.to_ctx()).is_err() {
        return Ok(wgsl);
    }
    // naga's writer emits the module's structs in arena order, skipping predeclared ones.
    let predeclared: Vec<Handle<Type>> = module.special_types.predeclared_types.values().copied().collect();
    let mut attributes: Vec<Vec<String>> = Vec::new();
    for (handle, ty) in module.types.iter() {
        let TypeInner::Struct { members, .. } = &ty.inner else { continue };
        if predeclared.contains(&handle)
            || Some(handle) == module.special_types.external_texture_params
            || Some(handle) == module.special_types.external_texture_transfer_function
        {
            continue;
        }
        let layout = ty.name.as_ref().and_then(|n| host.structs.get(n));
        attributes.push(
            members
                .iter()
                .enumerate()
                .map(|(i, member)| {
                    let Some(&(alignment, size)) = layout.and_then(|l| l.members.get(i)) else {
                        return String::new();
                    };
                    let natural = &layouter[member.ty];
                    let mut written = String::new();
                    if alignment != natural.alignment.round_up(1) {
                        written.push_str(&format!("@align({alignment}) "));
                    }
                    if size != natural.size {
                        written.push_str(&format!("@size({size}) "));
                    }
                    written
                })
                .collect(),
        );
    }
    if attributes.iter().flatten().all(String::is_empty) {
        return Ok(wgsl);
    }
    let mut out = String::with_capacity(wgsl.len() + 64);
    let mut structs = attributes.iter();
    let mut pending: std::slice::Iter<String> = [].iter();
    for line in wgsl.split_inclusive('\n') {
        if line.starts_with("struct ") && line.trim_end().ends_with('{') {
            pending = match structs.next() {
                Some(members) => members.iter(),
                None => return Err(writer_mismatch()),
            };
            out.push_str(line);
            continue;
        }
        if line.starts_with('}') && pending.len() > 0 {
            return Err(writer_mismatch());
        }
        match line.strip_prefix("    ").filter(|_| pending.len() > 0) {
            Some(member) => {
                out.push_str("    ");
                out.push_str(pending.next().map_or("", String::as_str));
                out.push_str(member);
            }
            None => out.push_str(line),
        }
    }
    if structs.next().is_some() {
        return Err(writer_mismatch());
    }
    Ok(out)
}

fn writer_mismatch() -> Diagnostic {
    Diagnostic::error("K0409", "the WGSL writer's structs are not where kiln expects them")
        .note("kiln writes each struct member's `@align`/`@size` into naga's WGSL; this naga writes structs differently")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn struct_declarations_are_read_with_their_layout_attributes() {
        let text = "/* struct Hidden { a: f32 } */ struct A { @align(32) a: f32, // x\n @size(N) @location(0) b: array<vec4<f32>, 2>, c: mat2x2<f32> }\nfn f() {}";
        let structs = scan_structs(text);
        assert_eq!(structs.len(), 1);
        let a = &structs[0];
        assert_eq!(a.name, "A");
        let names: Vec<&str> = a.members.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["a", "b", "c"]);
        assert_eq!(a.members[0].align.as_ref().map(|x| x.expression.as_str()), Some("32"));
        assert_eq!(a.members[1].size.as_ref().map(|x| x.expression.as_str()), Some("N"));
        assert_eq!(&text[a.members[1].size.as_ref().map(|x| x.range.clone()).unwrap()], "@size(N)");
        assert!(a.members[2].align.is_none() && a.members[2].size.is_none());
    }
}
