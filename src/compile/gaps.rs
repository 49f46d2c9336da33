//! SPIR-V where naga's writer (30) cannot write it: a module with a construct the writer lays
//! out against Vulkan's rules, or on which the writer fails or panics, ships as WGSL only, and the
//! build warns once per variant naming the construct (K0415, said by the build layer from the
//! module's reflection, so a module from a cache warns too). naga's validator accepts all of these,
//! so refusing them would drop valid WGSL.
//!
//! Known before writing: a matrix in a uniform buffer that is an f16 matrix with 3 or 4 rows
//! (column stride 8; Vulkan's uniform layout needs 16), or a two-row matrix below the buffer's
//! own struct (naga decomposes two-row matrices for std140 only there); an array type used both
//! by an `alias` and by its own name (naga writes two types, and a store between them is invalid).

use super::panics::contain_panics;
use super::wgsl::WriterNames;
use crate::reflect::{MatrixProblem, SpirvGap};
use naga::common::wgsl::TypeContext;
use naga::{AddressSpace, Handle, Module, Type, TypeInner, VectorSize};

/// The first construct of a module, cut to its entry point, that naga's SPIR-V writer gets wrong.
pub(super) fn before_writing(module: &Module) -> Option<SpirvGap> {
    uniform_matrix(module).or_else(|| aliased_array(module))
}

/// An array type used both by an alias's name and by its own: naga keeps them apart (the alias's
/// type carries its name), and its SPIR-V writer declares each, so a value of one stored into
/// the other is a type mismatch. The module is cut to its entry point, so both are used there.
fn aliased_array(module: &Module) -> Option<SpirvGap> {
    let mut seen: std::collections::HashMap<&TypeInner, Handle<Type>> = std::collections::HashMap::new();
    for (handle, ty) in module.types.iter() {
        if !matches!(ty.inner, TypeInner::Array { .. }) {
            continue;
        }
        if let Some(&other) = seen.get(&ty.inner) {
            let named = [handle, other].into_iter().find_map(|h| module.types[h].name.clone());
            let alias = named.unwrap_or_default();
            return Some(SpirvGap::AliasedArray {
                alias,
                ty: WriterNames::new(module).type_to_string(handle),
            });
        }
        seen.insert(&ty.inner, handle);
    }
    None
}

/// The first matrix of a uniform buffer that naga's SPIR-V writer lays out wrongly.
fn uniform_matrix(module: &Module) -> Option<SpirvGap> {
    module.global_variables.iter().filter(|(_, g)| g.space == AddressSpace::Uniform).find_map(
        |(_, global)| {
            let buffer = global.name.clone().unwrap_or_default();
            let (member, matrix, problem) = match &module.types[global.ty].inner {
                // Its own struct's members are where naga's std140 rewrite reaches.
                TypeInner::Struct { members, .. } => members.iter().find_map(|m| {
                    let name = format!(
                        "{}.{}",
                        struct_name(module, global.ty),
                        m.name.as_deref().unwrap_or_default()
                    );
                    matrix_problem(module, m.ty, name, false)
                }),
                _ => matrix_problem(module, global.ty, buffer.clone(), false),
            }?;
            Some(SpirvGap::UniformMatrix { buffer, member, matrix, problem })
        },
    )
}

/// `words` naga's SPIR-V writer gives, or why it gave none: its error, or its panic.
pub(super) fn write(
    module: &Module,
    info: &naga::valid::ModuleInfo,
    options: &naga::back::spv::Options,
    pipeline: &naga::back::spv::PipelineOptions,
) -> Result<Vec<u32>, SpirvGap> {
    match contain_panics(|| naga::back::spv::write_vec(module, info, options, Some(pipeline))) {
        Ok(Ok(words)) => Ok(words),
        Ok(Err(error)) => Err(SpirvGap::Writer { message: error.to_string() }),
        Err(panic) => {
            Err(SpirvGap::Writer { message: format!("it panicked at {}: {}", panic.location, panic.message) })
        }
    }
}

/// A matrix naga gets wrong in `ty` (a member named `name`), `nested` below the buffer's own
/// struct: (where, its type, what is wrong).
fn matrix_problem(
    module: &Module,
    ty: Handle<Type>,
    name: String,
    nested: bool,
) -> Option<(String, String, MatrixProblem)> {
    match &module.types[ty].inner {
        &TypeInner::Matrix { rows, scalar, .. } => {
            let problem = if scalar.width == 2 && rows != VectorSize::Bi {
                MatrixProblem::F16Rows
            } else if rows == VectorSize::Bi && nested {
                MatrixProblem::NestedTwoRows
            } else {
                return None;
            };
            Some((name, WriterNames::new(module).type_to_string(ty), problem))
        }
        TypeInner::Array { base, .. } => matrix_problem(module, *base, name, nested),
        TypeInner::Struct { members, .. } => members.iter().find_map(|m| {
            let name = format!("{}.{}", struct_name(module, ty), m.name.as_deref().unwrap_or_default());
            matrix_problem(module, m.ty, name, true)
        }),
        _ => None,
    }
}

fn struct_name(module: &Module, ty: Handle<Type>) -> &str {
    module.types[ty].name.as_deref().unwrap_or_default()
}
