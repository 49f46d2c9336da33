//! WGSL out: naga's writer, with the layouts of the source written back and kiln's repairs where
//! naga (30) writes text that its own front end refuses, so that every WGSL module kiln ships
//! loads again (wgpu hands it to naga at run time):
//!
//! - a value of a type WGSL cannot name (`modf`'s, `frexp`'s and `atomicCompareExchangeWeak`'s
//!   results) is declared with naga's internal type name (`var a: _modf_result_f32_;`): it is
//!   declared by its zero value instead (`var a = modf(f32());`, whose fields are zero too), or
//!   where it is first assigned (`var r = atomicCompareExchangeWeak(...)`);
//! - a division (or another operator) of two constants that naga could not fold (`1f / 0f`: WGSL
//!   makes that an error only in a constant expression) is written as a constant expression: the
//!   right operand goes through a function, which no constant expression may call;
//! - an array an `override` sizes is written without its element type (`array<size>`).
//!
//! A repaired module is parsed and validated again before it is shipped; one that still does not
//! load is an error (K0409), never a module that fails when a pipeline is made.

use super::layout::{self, HostLayout};
use crate::diagnostics::Diagnostic;
use naga::common::wgsl::TypeContext;
use naga::proc::NameKey;
use naga::{Handle, Module, TypeInner};
use std::fmt::Write as _;

/// WGSL for a validated module, with the struct layouts of the source (naga's writer drops
/// `@align`/`@size`). naga's writer emits `enable f16;` only when a type declaration
/// uses f16, not for f16 arithmetic in expressions (conversions, `h` literals), which the WGSL
/// front end then rejects; a module allowed f16 always gets the directive.
pub(super) fn write(
    module: &Module,
    info: &naga::valid::ModuleInfo,
    capabilities: naga::valid::Capabilities,
    host: &HostLayout,
) -> Result<String, Diagnostic> {
    let wgsl = naga::back::wgsl::write_string(module, info, naga::back::wgsl::WriterFlags::empty())
        .map_err(|e| super::stage::backend_error("WGSL", e.to_string()))?;
    let wgsl = layout::annotate_wgsl(wgsl, module, host)?;
    let wgsl = override_workgroup_sizes(wgsl, module);
    let (wgsl, repaired) = repair(wgsl, module);
    let needs_enable = capabilities.contains(naga::valid::Capabilities::SHADER_FLOAT16)
        && !wgsl.lines().any(|line| line.trim() == "enable f16;");
    let wgsl = if needs_enable { format!("enable f16;\n{wgsl}") } else { wgsl };
    if repaired {
        loads_again(&wgsl, capabilities)?;
    }
    Ok(wgsl)
}

/// naga's WGSL writer (30) writes a workgroup size an `override` gives as 1: the entry point's
/// `@workgroup_size` is written again with the constants' names. (Sizes given by other
/// expressions are refused first: `stage::check_override_defaults`.)
fn override_workgroup_sizes(wgsl: String, module: &Module) -> String {
    let Some(entry) = module.entry_points.first() else { return wgsl };
    let Some(sizes) = &entry.workgroup_size_overrides else { return wgsl };
    let dimension = |i: usize| match sizes[i].map(|e| &module.global_expressions[e]) {
        Some(naga::Expression::Override(o)) => module.overrides[*o].name.clone().unwrap_or_default(),
        _ => entry.workgroup_size[i].to_string(),
    };
    let Some(function) = wgsl.find(&format!("\nfn {}(", entry.name)) else { return wgsl };
    let Some(start) = wgsl[..function].rfind("@workgroup_size(") else { return wgsl };
    let Some(end) = wgsl[start..function].find(')').map(|e| start + e + 1) else { return wgsl };
    format!(
        "{}@workgroup_size({}, {}, {}){}",
        &wgsl[..start],
        dimension(0),
        dimension(1),
        dimension(2),
        &wgsl[end..]
    )
}

/// `wgsl` with the constructs naga misspells written so that they load, and whether any was.
/// Each repair first asks the module whether it has the construct, so most modules cost a few
/// comparisons and no text is searched.
fn repair(mut wgsl: String, module: &Module) -> (String, bool) {
    let pending = module
        .types
        .iter()
        .any(|(_, ty)| matches!(ty.inner, TypeInner::Array { size: naga::ArraySize::Pending(_), .. }));
    let unfolded = unfolded_constant_operations(module);
    if !pending && module.special_types.predeclared_types.is_empty() && unfolded.is_empty() {
        return (wgsl, false);
    }
    let names = WriterNames::new(module);
    for (_, ty) in module.types.iter() {
        if let TypeInner::Array { base, size: naga::ArraySize::Pending(constant), .. } = ty.inner {
            let size = names.name(NameKey::Override(constant));
            let base = names.type_to_string(base);
            wgsl = wgsl.replace(&format!("array<{size}>"), &format!("array<{base}, {size}>"));
        }
    }
    for (kind, &ty) in &module.special_types.predeclared_types {
        let (function, size, scalar) = match *kind {
            naga::PredeclaredType::ModfResult { size, scalar } => ("modf", size, scalar),
            naga::PredeclaredType::FrexpResult { size, scalar } => ("frexp", size, scalar),
            // No expression without an atomic gives one: the variable is declared where it is
            // first given a value instead.
            naga::PredeclaredType::AtomicCompareExchangeWeakResult(_) => {
                wgsl = declared_at_first_assignment(&wgsl, names.name(NameKey::Type(ty)));
                continue;
            }
        };
        let argument = match size {
            Some(size) => TypeInner::Vector { size, scalar },
            None => TypeInner::Scalar(scalar),
        };
        let zero = format!("{function}({}())", names.inner_text(&argument));
        wgsl = wgsl.replace(&format!(": {};", names.name(NameKey::Type(ty))), &format!(" = {zero};"));
    }
    // One identity function per scalar type, named apart from everything the module declares.
    let mut helpers: Vec<(String, String)> = Vec::new();
    for (left, op, right) in unfolded {
        let scalar = names.inner_text(&TypeInner::Scalar(right.scalar()));
        let helper = match helpers.iter().find(|(_, s)| *s == scalar) {
            Some((helper, _)) => helper.clone(),
            None => {
                let mut helper = format!("kiln_runtime_{scalar}");
                while wgsl.contains(&helper) {
                    helper.push('_');
                }
                helpers.push((helper.clone(), scalar));
                helper
            }
        };
        let (left, right) = (literal_text(left), literal_text(right));
        wgsl = wgsl.replace(&format!("({left} {op} {right})"), &format!("({left} {op} {helper}({right}))"));
    }
    for (helper, scalar) in helpers {
        let _ = write!(wgsl, "\nfn {helper}(value: {scalar}) -> {scalar} {{\n    return value;\n}}\n");
    }
    (wgsl, true)
}

/// `wgsl` with each `var NAME: TYPE;` (naga declares a function's variables first) removed and
/// its first assignment, `NAME = value;` at the same depth with no use of `NAME` between,
/// made the declaration, `var NAME = value;`, whose type WGSL infers. Others are left as they are
/// (the repaired module is loaded again, so one left is an error, not a module that fails later).
fn declared_at_first_assignment(wgsl: &str, type_name: &str) -> String {
    let mut lines: Vec<String> = wgsl.lines().map(str::to_string).collect();
    let suffix = format!(": {type_name};");
    let mut at = 0;
    while at < lines.len() {
        let line = &lines[at];
        let indent = &line[..line.len() - line.trim_start().len()];
        let Some(name) = line.trim_start().strip_prefix("var ").and_then(|rest| rest.strip_suffix(&suffix))
        else {
            at += 1;
            continue;
        };
        let (name, indent) = (name.to_string(), indent.to_string());
        let mentions =
            |text: &str| text.split(|c: char| !(c.is_alphanumeric() || c == '_')).any(|w| w == name);
        let first_use = (at + 1..lines.len()).find(|&i| mentions(&lines[i]));
        let assignment = format!("{indent}{name} = ");
        match first_use {
            Some(i) if lines[i].starts_with(&assignment) => {
                lines[i] = format!("{indent}var {}", &lines[i][indent.len()..]);
                lines.remove(at);
            }
            _ => at += 1,
        }
    }
    let mut out = lines.join("\n");
    out.push('\n');
    out
}

/// The operations of two literals left in a function: naga folds every one it can, so each is one
/// whose value is not a constant's (a division by zero, an overflow), which WGSL allows at run
/// time but refuses in the constant expression naga's writer makes of it.
fn unfolded_constant_operations(module: &Module) -> Vec<(naga::Literal, &'static str, naga::Literal)> {
    let functions =
        module.functions.iter().map(|(_, f)| f).chain(module.entry_points.iter().map(|e| &e.function));
    let mut found = Vec::new();
    for function in functions {
        for (_, expression) in function.expressions.iter() {
            let naga::Expression::Binary { op, left, right } = *expression else { continue };
            let (naga::Expression::Literal(left), naga::Expression::Literal(right)) =
                (&function.expressions[left], &function.expressions[right])
            else {
                continue;
            };
            found.push((*left, naga::back::binary_operation_str(op), *right));
        }
    }
    found
}

/// A literal as naga's WGSL writer (30) writes it.
fn literal_text(literal: naga::Literal) -> String {
    use naga::Literal as L;
    match literal {
        L::F16(v) => format!("{v}h"),
        L::F32(v) => format!("{v}f"),
        L::U16(v) => format!("u16({v})"),
        L::I16(v) => format!("i16({v})"),
        L::U32(v) => format!("{v}u"),
        L::I32(i32::MIN) => format!("i32({})", i32::MIN),
        L::I32(v) => format!("{v}i"),
        L::Bool(v) => format!("{v}"),
        L::F64(v) => format!("{v:?}lf"),
        L::I64(i64::MIN) => format!("i64({} - 1)", i64::MIN + 1),
        L::I64(v) => format!("{v}li"),
        L::U64(v) => format!("{v:?}lu"),
        L::AbstractInt(v) => format!("{v}"),
        L::AbstractFloat(v) => format!("{v:?}"),
    }
}

/// The names naga's WGSL writer gives a module's declarations: its namer, set up as the writer
/// sets it up (and, through [`TypeContext`], a type as the writer spells it).
pub(super) struct WriterNames<'a> {
    module: &'a Module,
    names: naga::FastHashMap<NameKey, String>,
}

impl<'a> WriterNames<'a> {
    pub(super) fn new(module: &'a Module) -> WriterNames<'a> {
        let mut names = naga::FastHashMap::default();
        naga::proc::Namer::default().reset(
            module,
            &naga::keywords::wgsl::RESERVED_SET,
            &naga::keywords::wgsl::BUILTIN_IDENTIFIER_SET,
            naga::proc::CaseInsensitiveKeywordSet::empty(),
            &["__", "_naga"],
            &mut names,
        );
        WriterNames { module, names }
    }

    fn name(&self, key: NameKey) -> &str {
        self.names.get(&key).map_or("", String::as_str)
    }

    fn inner_text(&self, inner: &TypeInner) -> String {
        let mut text = String::new();
        let _ = self.write_type_inner(inner, &mut text);
        text
    }
}

impl TypeContext for WriterNames<'_> {
    fn lookup_type(&self, handle: Handle<naga::Type>) -> &naga::Type {
        &self.module.types[handle]
    }

    fn type_name(&self, handle: Handle<naga::Type>) -> &str {
        self.name(NameKey::Type(handle))
    }

    fn write_override<W: std::fmt::Write>(
        &self,
        constant: Handle<naga::Override>,
        out: &mut W,
    ) -> std::fmt::Result {
        out.write_str(self.name(NameKey::Override(constant)))
    }

    fn write_unnamed_struct<W: std::fmt::Write>(&self, _: &TypeInner, _: &mut W) -> std::fmt::Result {
        // Every struct a module declares has a name in the namer's map.
        Err(std::fmt::Error)
    }
}

/// Whether kiln's WGSL for a module parses and validates again, as wgpu will load it.
fn loads_again(wgsl: &str, capabilities: naga::valid::Capabilities) -> Result<(), Diagnostic> {
    let refused = |message: String| {
        Diagnostic::error("K0409", format!("the WGSL naga's writer wrote does not load again: {message}")).note(
            "kiln repairs what naga's WGSL writer is known to misspell, and this module needs a repair it \
             lacks; please report it with this variant's `kiln preprocess` output",
        )
    };
    let module = naga::front::wgsl::parse_str(wgsl).map_err(|e| refused(e.message().to_string()))?;
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
        .validate(&module)
        .map_err(|e| refused(e.as_inner().to_string()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// naga's own WGSL for each construct does not load again, and kiln's repaired WGSL does
    /// (the cases come from Tint's end-to-end tests, where they were found).
    #[test]
    fn each_construct_naga_misspells_is_repaired_so_that_it_loads() {
        let capabilities = naga::valid::Capabilities::all();
        for source in [
            "@compute @workgroup_size(1) fn main() { var a = modf(1.5); let w = a.whole; }",
            "@compute @workgroup_size(1) fn main() { var a = frexp(vec2(1.5, 2.0)); let e = a.exp; }",
            "@compute @workgroup_size(1) fn main() { let a = 1.0; let b = 0.0; let r = a / b; }",
            "override size = 2; var<workgroup> v: array<f32, size>;\n\
             @compute @workgroup_size(1) fn main() { let x = v[0]; }",
            "var<workgroup> a: atomic<i32>;\n\
             @compute @workgroup_size(1) fn main() { var r = atomicCompareExchangeWeak(&a, 1i, 1i); }",
        ] {
            let module = naga::front::wgsl::parse_str(source).expect("parses");
            let info = naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
                .validate(&module)
                .expect("validates");
            let plain =
                naga::back::wgsl::write_string(&module, &info, naga::back::wgsl::WriterFlags::empty())
                    .expect("writes");
            assert!(loads_again(&plain, capabilities).is_err(), "naga's own WGSL loads now:\n{plain}");
            let (repaired, changed) = repair(plain, &module);
            assert!(changed);
            if let Err(d) = loads_again(&repaired, capabilities) {
                panic!("{source}\n{repaired}\n{}", d.message);
            }
        }
    }
}
