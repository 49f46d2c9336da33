//! naga's validation errors in a user's words: types and functions by name rather than by arena
//! handle (`Some([3])`), labels that say what is there rather than `naga::ir::Expression [3]`.
//! Naming things also makes one mistake the same message in every variant, so a diagnostic that
//! several variants share is reported once, with the variants it occurs in.

use naga::common::wgsl::TypeContext;
use naga::proc::TypeResolution;
use naga::valid::{EntryPointError, ExpressionError, FunctionError, ValidationError};

/// The message for a validation error of `module`.
pub(super) fn validation_message(error: &ValidationError, module: &naga::Module) -> String {
    match error {
        ValidationError::Function { name, source, .. } => {
            format!("in function `{name}`: {}", function_message(source, module))
        }
        ValidationError::EntryPoint { stage, name, source: EntryPointError::Function(source) } => {
            format!(
                "in the {} entry point `{name}`: {}",
                stage_name(*stage),
                function_message(source, module)
            )
        }
        ValidationError::EntryPoint { stage, name, source } => {
            format!("the {} entry point `{name}` is invalid: {}", stage_name(*stage), chain(source))
        }
        other => chain(other),
    }
}

fn stage_name(stage: naga::ShaderStage) -> &'static str {
    match stage {
        naga::ShaderStage::Vertex => "vertex",
        naga::ShaderStage::Fragment => "fragment",
        naga::ShaderStage::Compute => "compute",
        _ => "shader",
    }
}

fn function_message(error: &FunctionError, module: &naga::Module) -> String {
    let types = module.to_ctx();
    let inner = |ty: &naga::TypeInner| types.type_resolution_to_string(&TypeResolution::Value(ty.clone()));
    match error {
        FunctionError::InvalidReturnType { expression: Some(_), expected_ty: Some(ty) } => {
            format!("the value returned is not a `{}`, the function's return type", types.type_to_string(*ty))
        }
        FunctionError::InvalidReturnType { expression: Some(_), expected_ty: None } => {
            "a value is returned from a function that declares no return type".into()
        }
        FunctionError::InvalidReturnType { expression: None, expected_ty: Some(ty) } => {
            format!("`return` has no value, but the function returns `{}`", types.type_to_string(*ty))
        }
        FunctionError::Expression {
            source: ExpressionError::InvalidBinaryOperandTypes { op, lhs_type, rhs_type, .. },
            ..
        } => format!("`{}` cannot take `{}` and `{}`", operator(*op), inner(lhs_type), inner(rhs_type)),
        FunctionError::Expression {
            source: ExpressionError::InvalidImageCoordinateType(dimension, _),
            ..
        } => {
            let dimension = match dimension {
                naga::ImageDimension::D1 => "1D",
                naga::ImageDimension::D2 => "2D",
                naga::ImageDimension::D3 => "3D",
                naga::ImageDimension::Cube => "cube",
            };
            format!("the texture coordinates do not have the type a {dimension} texture takes")
        }
        FunctionError::Expression {
            source: ExpressionError::InvalidArgumentType(function, index, _),
            ..
        } => {
            let name =
                naga::common::wgsl::TryToWgsl::try_to_wgsl(*function).unwrap_or("the built-in function");
            format!("argument {} of `{name}` has a type it does not take", index + 1)
        }
        // naga's "Expression [N] is invalid" says nothing the label does not.
        FunctionError::Expression { source, .. } => chain(source),
        FunctionError::InvalidIfType(_) => "the `if` condition is not a `bool`".into(),
        FunctionError::InvalidSwitchType(_) => "the `switch` selector is not an `i32` or `u32`".into(),
        FunctionError::InvalidStoreTypes { .. } => {
            "the value stored does not have the type of its destination".into()
        }
        other => chain(other),
    }
}

fn operator(op: naga::BinaryOperator) -> &'static str {
    use naga::BinaryOperator as B;
    match op {
        B::Add => "+",
        B::Subtract => "-",
        B::Multiply => "*",
        B::Divide => "/",
        B::Modulo => "%",
        B::Equal => "==",
        B::NotEqual => "!=",
        B::Less => "<",
        B::LessEqual => "<=",
        B::Greater => ">",
        B::GreaterEqual => ">=",
        B::And => "&",
        B::ExclusiveOr => "^",
        B::InclusiveOr => "|",
        B::LogicalAnd => "&&",
        B::LogicalOr => "||",
        B::ShiftLeft => "<<",
        B::ShiftRight => ">>",
    }
}

/// naga's own text for an error and its causes, with arena handles left out: they number
/// things in naga's module, which the user never sees, and differ between variants.
fn chain(error: &dyn std::error::Error) -> String {
    let mut message = without_handles(&error.to_string());
    let mut source = error.source();
    while let Some(inner) = source {
        message.push_str(": ");
        message.push_str(&without_handles(&inner.to_string()));
        source = inner.source();
    }
    message
}

/// Drops `[N]`, `Some([N])` and `None` handle mentions, and the space before them.
fn without_handles(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(['[', 'S']) {
        let (before, from) = rest.split_at(at);
        let handle = |s: &str| -> Option<usize> {
            let digits = s.strip_prefix('[')?;
            let n = digits.find(|c: char| !c.is_ascii_digit())?;
            (n > 0 && digits[n..].starts_with(']')).then_some(n + 2)
        };
        let skip = handle(from).or_else(|| {
            let inner = from.strip_prefix("Some(")?;
            handle(inner).filter(|&n| inner[n..].starts_with(')')).map(|n| n + 6)
        });
        match skip {
            Some(n) => {
                out.push_str(before.trim_end_matches(' '));
                rest = &from[n..];
            }
            None => {
                out.push_str(before);
                out.push_str(&from[..1]);
                rest = &from[1..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// What a label of naga's says is at its span: `naga::ir::Expression [3]` becomes "this
/// expression", `naga::ir::Function [2]` "in this function"; other labels are kept.
pub(super) fn label(text: &str) -> String {
    let Some(kind) = text.strip_prefix("naga::ir::").and_then(|rest| rest.split(' ').next()) else {
        return text.to_string();
    };
    match kind {
        "Expression" => "this expression".into(),
        "Function" => "in this function".into(),
        "Type" => "this type".into(),
        "GlobalVariable" => "this global variable".into(),
        "LocalVariable" => "this local variable".into(),
        "Constant" => "this constant".into(),
        "Override" => "this override".into(),
        _ => "here".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn handles_are_left_out() {
        assert_eq!(
            without_handles(
                "The `return` expression Some([9]) does not match the declared return type Some([1])"
            ),
            "The `return` expression does not match the declared return type"
        );
        assert_eq!(
            without_handles("Operand [3] has invalid type. Some text [x]"),
            "Operand has invalid type. Some text [x]"
        );
        assert_eq!(label("naga::ir::Expression [9]"), "this expression");
        assert_eq!(label("invalid return"), "invalid return");
    }
}
