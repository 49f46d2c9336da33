//! `#if` / `#elif` expressions: C integer arithmetic over macros, `defined X` and `defined(X)`.
//! Identifiers that name no macro are 0, as in C. Offsets in errors are byte offsets into the
//! expression text, so callers can turn them into spans.

/// Expansion deeper than this is taken to be a runaway macro chain.
pub const MAX_EXPANSION_DEPTH: usize = 64;

/// Parentheses and unary operators nested deeper than this are refused rather than recursed into
/// (C guarantees 63 levels of parentheses).
pub const MAX_NESTING: usize = 64;

#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ExprError {
    /// Parentheses or unary operators nested past [`MAX_NESTING`].
    NestedTooDeep {
        offset: usize,
    },
    /// The expression is not well formed; `expected` says what should have come at `offset`.
    Malformed {
        offset: usize,
        expected: &'static str,
    },
    DivisionByZero {
        offset: usize,
    },
    ExpansionTooDeep {
        offset: usize,
        name: String,
    },
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Num(i64),
    Ident(String),
    Op(&'static str),
}

/// Operators, longest first so that `<=` is not read as `<`.
const OPERATORS: [&str; 24] = [
    "||", "&&", "==", "!=", "<=", ">=", "<<", ">>", "<", ">", "+", "-", "*", "/", "%", "!", "~", "&", "|",
    "^", "(", ")", "?", ":",
];

fn tokenize(text: &str, base: usize) -> Result<Vec<(Tok, usize)>, ExprError> {
    let bytes = text.as_bytes();
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let b = bytes[i];
        if b.is_ascii_whitespace() {
            i += 1;
        } else if b.is_ascii_digit() {
            let start = i;
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            let literal = text[start..i].trim_end_matches(['u', 'U', 'l', 'L']);
            let value = match literal.strip_prefix("0x").or_else(|| literal.strip_prefix("0X")) {
                Some(hex) => i64::from_str_radix(hex, 16),
                None if literal.len() > 1 && literal.starts_with('0') => {
                    i64::from_str_radix(&literal[1..], 8)
                }
                None => literal.parse(),
            };
            let value =
                value.map_err(|_| ExprError::Malformed { offset: base + start, expected: "an integer" })?;
            tokens.push((Tok::Num(value), base + start));
        } else if b.is_ascii_alphabetic() || b == b'_' {
            let start = i;
            while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                i += 1;
            }
            tokens.push((Tok::Ident(text[start..i].to_string()), base + start));
        } else if let Some(op) = OPERATORS.iter().find(|op| text[i..].starts_with(**op)) {
            tokens.push((Tok::Op(op), base + i));
            i += op.len();
        } else {
            return Err(ExprError::Malformed {
                offset: base + i,
                expected: "an operator, a number or a name",
            });
        }
    }
    Ok(tokens)
}

/// Replaces macro names by their values (recursively) and `defined` forms by 0 or 1. Every token
/// produced by an expansion keeps the offset of the name it came from.
fn expand(
    tokens: Vec<(Tok, usize)>,
    lookup: &dyn Fn(&str) -> Option<String>,
    expanding: &mut Vec<String>,
) -> Result<Vec<(Tok, usize)>, ExprError> {
    let mut out = Vec::with_capacity(tokens.len());
    let mut iter = tokens.into_iter().peekable();
    while let Some((tok, offset)) = iter.next() {
        match tok {
            Tok::Ident(name) if name == "defined" => {
                let parenthesised = iter.next_if(|(t, _)| *t == Tok::Op("("));
                let Some((Tok::Ident(target), _)) = iter.next() else {
                    return Err(ExprError::Malformed { offset, expected: "a macro name after `defined`" });
                };
                if parenthesised.is_some() && iter.next().map(|(t, _)| t) != Some(Tok::Op(")")) {
                    return Err(ExprError::Malformed { offset, expected: "`)` after `defined(NAME`" });
                }
                out.push((Tok::Num(i64::from(lookup(&target).is_some())), offset));
            }
            Tok::Ident(name) => match lookup(&name) {
                // A macro mentioning itself stops expanding there, as in C.
                Some(value) if !expanding.contains(&name) => {
                    if expanding.len() >= MAX_EXPANSION_DEPTH {
                        return Err(ExprError::ExpansionTooDeep { offset, name });
                    }
                    let inner = tokenize(&value, 0)?.into_iter().map(|(t, _)| (t, offset)).collect();
                    expanding.push(name);
                    let expanded = expand(inner, lookup, expanding)?;
                    expanding.pop();
                    out.extend(expanded);
                }
                _ => out.push((Tok::Num(0), offset)),
            },
            other => out.push((other, offset)),
        }
    }
    Ok(out)
}

/// Evaluates an `#if` expression. `lookup` gives a macro's value (`Some("")` for `#define X`).
pub fn evaluate(text: &str, lookup: &dyn Fn(&str) -> Option<String>) -> Result<i64, ExprError> {
    let tokens = expand(tokenize(text, 0)?, lookup, &mut Vec::new())?;
    let mut parser = Parser { tokens, at: 0, end: text.len(), depth: 0 };
    let value = parser.ternary()?;
    match parser.tokens.get(parser.at) {
        None => Ok(value),
        Some(&(_, offset)) => {
            Err(ExprError::Malformed { offset, expected: "an operator or the end of the line" })
        }
    }
}

struct Parser {
    tokens: Vec<(Tok, usize)>,
    at: usize,
    end: usize,
    depth: usize,
}

/// Binary operators by precedence, loosest first.
const LEVELS: [&[&str]; 9] = [
    &["||"],
    &["&&"],
    &["|"],
    &["^"],
    &["&"],
    &["==", "!="],
    &["<", ">", "<=", ">="],
    &["<<", ">>"],
    &["+", "-"],
];

impl Parser {
    fn offset(&self) -> usize {
        self.tokens.get(self.at).map_or(self.end, |(_, o)| *o)
    }

    fn eat(&mut self, op: &str) -> bool {
        let hit = matches!(self.tokens.get(self.at), Some((Tok::Op(o), _)) if *o == op);
        self.at += usize::from(hit);
        hit
    }

    fn ternary(&mut self) -> Result<i64, ExprError> {
        let condition = self.binary(0)?;
        if !self.eat("?") {
            return Ok(condition);
        }
        let then = self.ternary()?;
        if !self.eat(":") {
            return Err(ExprError::Malformed { offset: self.offset(), expected: "`:`" });
        }
        let otherwise = self.ternary()?;
        Ok(if condition != 0 { then } else { otherwise })
    }

    fn binary(&mut self, level: usize) -> Result<i64, ExprError> {
        if level == LEVELS.len() {
            return self.product();
        }
        let mut left = self.binary(level + 1)?;
        'outer: loop {
            for op in LEVELS[level] {
                if self.eat(op) {
                    let right = self.binary(level + 1)?;
                    left = match *op {
                        "||" => i64::from(left != 0 || right != 0),
                        "&&" => i64::from(left != 0 && right != 0),
                        "|" => left | right,
                        "^" => left ^ right,
                        "&" => left & right,
                        "==" => i64::from(left == right),
                        "!=" => i64::from(left != right),
                        "<" => i64::from(left < right),
                        ">" => i64::from(left > right),
                        "<=" => i64::from(left <= right),
                        ">=" => i64::from(left >= right),
                        "<<" => left.wrapping_shl(right as u32),
                        ">>" => left.wrapping_shr(right as u32),
                        "+" => left.wrapping_add(right),
                        _ => left.wrapping_sub(right),
                    };
                    continue 'outer;
                }
            }
            return Ok(left);
        }
    }

    fn product(&mut self) -> Result<i64, ExprError> {
        let mut left = self.unary()?;
        loop {
            let offset = self.offset();
            let op = if self.eat("*") {
                "*"
            } else if self.eat("/") {
                "/"
            } else if self.eat("%") {
                "%"
            } else {
                return Ok(left);
            };
            let right = self.unary()?;
            left = match op {
                "*" => left.wrapping_mul(right),
                _ if right == 0 => return Err(ExprError::DivisionByZero { offset }),
                "/" => left.wrapping_div(right),
                _ => left.wrapping_rem(right),
            };
        }
    }

    fn unary(&mut self) -> Result<i64, ExprError> {
        self.depth += 1;
        let value = self.unary_inner();
        self.depth -= 1;
        value
    }

    fn unary_inner(&mut self) -> Result<i64, ExprError> {
        if self.depth > MAX_NESTING {
            return Err(ExprError::NestedTooDeep { offset: self.offset() });
        }
        if self.eat("!") {
            return Ok(i64::from(self.unary()? == 0));
        }
        if self.eat("-") {
            return Ok(self.unary()?.wrapping_neg());
        }
        if self.eat("+") {
            return self.unary();
        }
        if self.eat("~") {
            return Ok(!self.unary()?);
        }
        if self.eat("(") {
            let value = self.ternary()?;
            if !self.eat(")") {
                return Err(ExprError::Malformed { offset: self.offset(), expected: "`)`" });
            }
            return Ok(value);
        }
        match self.tokens.get(self.at) {
            Some((Tok::Num(n), _)) => {
                self.at += 1;
                Ok(*n)
            }
            _ => Err(ExprError::Malformed { offset: self.offset(), expected: "a number, a name or `(`" }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn eval(text: &str) -> Result<i64, ExprError> {
        let macros = |name: &str| match name {
            "ONE" => Some("1".to_string()),
            "EMPTY" => Some(String::new()),
            "MAX_DIRECTIONAL_LIGHT_COUNT" => Some("4".to_string()),
            "TWICE" => Some("(MAX_DIRECTIONAL_LIGHT_COUNT * 2)".to_string()),
            "SELF" => Some("SELF + 1".to_string()),
            "PING" => Some("PONG".to_string()),
            "PONG" => Some("PING".to_string()),
            _ => None,
        };
        evaluate(text, &macros)
    }

    #[test]
    fn c_arithmetic_and_precedence() {
        assert_eq!(eval("1 + 2 * 3"), Ok(7));
        assert_eq!(eval("(1 + 2) * 3"), Ok(9));
        assert_eq!(eval("7 / 2 + 7 % 2"), Ok(4));
        assert_eq!(eval("1 < 2 == 1"), Ok(1));
        assert_eq!(eval("!0 && !!5 || 0"), Ok(1));
        assert_eq!(eval("-3 + +3 - ~0"), Ok(1));
        assert_eq!(eval("1 << 4 | 0x0F & 3 ^ 1"), Ok(18));
        assert_eq!(eval("0 ? 10 : 1 ? 20 : 30"), Ok(20));
        assert_eq!(eval("010 + 1u + 2L"), Ok(11));
    }

    #[test]
    fn macros_and_defined() {
        assert_eq!(eval("defined(ONE) && defined EMPTY"), Ok(1));
        assert_eq!(eval("defined(MISSING)"), Ok(0));
        assert_eq!(eval("MISSING + 1"), Ok(1), "unknown names are 0");
        assert_eq!(eval("TWICE == 8"), Ok(1));
        assert_eq!(eval("MAX_DIRECTIONAL_LIGHT_COUNT > 3"), Ok(1));
        assert_eq!(eval("SELF"), Ok(1), "self-reference stops expanding");
        assert_eq!(eval("PING"), Ok(0), "mutual recursion stops expanding");
    }

    #[test]
    fn errors_point_at_their_offset() {
        assert_eq!(eval("4 / (ONE - 1)"), Err(ExprError::DivisionByZero { offset: 2 }));
        assert_eq!(eval("1 % 0"), Err(ExprError::DivisionByZero { offset: 2 }));
        assert_eq!(eval("(1 + 2"), Err(ExprError::Malformed { offset: 6, expected: "`)`" }));
        assert_eq!(eval("1 +"), Err(ExprError::Malformed { offset: 3, expected: "a number, a name or `(`" }));
        assert_eq!(
            eval("1 2"),
            Err(ExprError::Malformed { offset: 2, expected: "an operator or the end of the line" })
        );
        assert_eq!(
            eval("1 @ 2"),
            Err(ExprError::Malformed { offset: 2, expected: "an operator, a number or a name" })
        );
        assert!(matches!(eval("defined"), Err(ExprError::Malformed { offset: 0, .. })));
        assert!(matches!(eval("defined(ONE"), Err(ExprError::Malformed { .. })));
        assert!(matches!(eval("EMPTY"), Err(ExprError::Malformed { .. })), "an empty macro leaves nothing");
        assert!(matches!(eval("99999999999999999999"), Err(ExprError::Malformed { offset: 0, .. })));
    }

    #[test]
    fn runaway_expansion_is_an_error() {
        let chain = |name: &str| {
            let n: usize = name.strip_prefix('M')?.parse().ok()?;
            Some(format!("M{}", n + 1))
        };
        assert!(matches!(evaluate("M0", &chain), Err(ExprError::ExpansionTooDeep { offset: 0, .. })));
    }

    #[test]
    fn deep_nesting_is_refused() {
        let deep = format!("{}1{}", "(".repeat(10_000), ")".repeat(10_000));
        assert!(matches!(eval(&deep), Err(ExprError::NestedTooDeep { .. })));
        assert!(matches!(eval(&"!".repeat(10_000)), Err(ExprError::NestedTooDeep { .. })));
        let fine = format!("{}1{}", "(".repeat(60), ")".repeat(60));
        assert_eq!(eval(&fine), Ok(1));
    }

    proptest::proptest! {
        #[test]
        fn arbitrary_expressions_never_panic(text in "[0-9a-zA-Z_ ()+*/%!~&|^<>=?:-]{0,60}") {
            let _ = eval(&text);
        }
    }

    #[test]
    fn overflow_wraps_instead_of_panicking() {
        assert_eq!(eval("9223372036854775807 + 1"), Ok(i64::MIN));
        assert_eq!(eval("(0 - 9223372036854775807 - 1) / -1"), Ok(i64::MIN));
        assert_eq!(eval("1 << 70"), Ok(1 << 6));
    }
}
