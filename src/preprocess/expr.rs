//! `#if` / `#elif` expressions as C evaluates them: macros expanded first (`defined X` and
//! `defined(X)` before), names left over are 0, and arithmetic in `intmax_t` / `uintmax_t` with
//! C's usual arithmetic conversions. The operands `&&`, `||` and `?:` do not evaluate are still
//! parsed but never divide by zero or shift out of range. Offsets in errors are byte offsets into
//! the expression text.

use super::macros::{Expander, Kind, Token, lex};
use std::borrow::Cow;

/// Parentheses nested deeper than this are refused rather than recursed into (C guarantees 63
/// levels, and counts only parentheses: unary operators are read in a loop and count for
/// nothing).
pub(super) const MAX_NESTING: usize = 64;

/// How deep `?:` may nest (`0 ? 0 : 0 ? 0 : ...`): each level is a few frames of this parser's
/// recursion, so 30,000 of them overflowed a thread's stack; a chain far longer than any real
/// header's is refused like parentheses past [`MAX_NESTING`].
const MAX_CONDITIONALS: usize = 256;

#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum ExprError {
    /// Parentheses nested past [`MAX_NESTING`], or `?:` past [`MAX_CONDITIONALS`].
    NestedTooDeep {
        offset: usize,
        /// What was expected instead.
        limit: &'static str,
    },
    /// The expression is not well formed; `expected` says what should have come at `offset`.
    Malformed {
        offset: usize,
        expected: &'static str,
    },
    DivisionByZero {
        offset: usize,
    },
    /// A shift by a negative count or by 64 or more (`offset` is the operator's).
    InvalidShift {
        offset: usize,
        count: String,
    },
}

/// A value of `intmax_t` or `uintmax_t`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Value {
    pub bits: u64,
    pub unsigned: bool,
}

impl Value {
    fn signed(v: i64) -> Value {
        Value { bits: v as u64, unsigned: false }
    }

    fn truth(b: bool) -> Value {
        Value::signed(i64::from(b))
    }

    fn is_true(self) -> bool {
        self.bits != 0
    }

    fn as_signed(self) -> i64 {
        self.bits as i64
    }
}

/// Evaluates an `#if` expression, expanding its macros with `expander` (whose errors stay in it).
pub(super) fn evaluate<'a>(text: &'a str, expander: &mut Expander<'_, 'a>) -> Result<bool, ExprError> {
    let tokens = defined(lex(text), expander)?;
    // `defined` written by a macro's expansion counts too, as gcc has it.
    let tokens = defined(expander.all(tokens), expander)?;
    let tokens = tokens
        .into_iter()
        .map(|t| Ok((operand(&t)?, t.at)))
        .collect::<Result<Vec<(Tok, usize)>, ExprError>>()?;
    let mut parser = Parser { tokens, at: 0, end: text.len(), depth: 0, conditionals: 0, dead: 0 };
    let value = parser.comma()?;
    match parser.tokens.get(parser.at) {
        None => Ok(value.is_true()),
        Some(&(_, offset)) => {
            Err(ExprError::Malformed { offset, expected: "an operator or the end of the line" })
        }
    }
}

/// Replaces `defined X` and `defined ( X )` by 1 or 0.
fn defined<'a>(tokens: Vec<Token<'a>>, expander: &Expander<'_, 'a>) -> Result<Vec<Token<'a>>, ExprError> {
    let mut out = Vec::with_capacity(tokens.len());
    let mut iter = tokens.into_iter().peekable();
    while let Some(token) = iter.next() {
        if token.kind != Kind::Ident || token.text != "defined" {
            out.push(token);
            continue;
        }
        let parenthesised = iter.next_if(|t| t.kind == Kind::Punct && t.text == "(").is_some();
        let malformed = ExprError::Malformed { offset: token.at, expected: "a macro name after `defined`" };
        let name = iter.next().filter(|t| t.kind == Kind::Ident).ok_or(malformed)?;
        if parenthesised && iter.next().is_none_or(|t| t.text != ")") {
            return Err(ExprError::Malformed { offset: token.at, expected: "`)` after `defined(NAME`" });
        }
        let value = if expander.macros.contains_key(&*name.text) { "1" } else { "0" };
        let mut number = token;
        (number.kind, number.text) = (Kind::Number, Cow::Borrowed(value));
        out.push(number);
    }
    Ok(out)
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Num(Value),
    Op(String),
}

fn operand(token: &Token<'_>) -> Result<Tok, ExprError> {
    let malformed = |expected| ExprError::Malformed { offset: token.at, expected };
    match token.kind {
        // A name no macro replaced is 0, as in C.
        Kind::Ident => Ok(Tok::Num(Value::signed(0))),
        Kind::Number => literal(&token.text).map(Tok::Num).map_err(malformed),
        Kind::Punct => Ok(Tok::Op(token.text.to_string())),
        Kind::Literal => Err(malformed("a number or a name (there are no strings in `#if`)")),
        Kind::Other => Err(malformed("an operator, a number or a name")),
    }
}

/// An integer literal with C's rules: decimal, octal (`017`), hexadecimal (`0x1F`) or binary
/// (`0b101`, as gcc allows), suffixes `u`, `l`, `ll` in either case and order; a literal too large
/// for `intmax_t` is unsigned.
fn literal(text: &str) -> Result<Value, &'static str> {
    let lower = text.to_ascii_lowercase();
    let (radix, digits_from) = if lower.starts_with("0x") {
        (16, 2)
    } else if lower.starts_with("0b") {
        (2, 2)
    } else if lower.starts_with('0') && lower.as_bytes().get(1).is_some_and(u8::is_ascii_digit) {
        (8, 1)
    } else {
        (10, 0)
    };
    let body = &text[digits_from..];
    let digits_len = body.bytes().take_while(|b| (*b as char).is_digit(radix)).count();
    let (digits, suffix) = body.split_at(digits_len);
    if radix == 10 && (suffix.starts_with(['.', 'e', 'E']) || text.starts_with('.')) {
        return Err("an integer (floating-point numbers are not allowed in `#if`)");
    }
    let valid_suffixes = ["", "u", "l", "ll", "ul", "lu", "ull", "llu"];
    let suffix_lower = suffix.to_ascii_lowercase();
    // `lL` mixes cases, which C does not allow.
    let mixed_ll = suffix.contains("lL") || suffix.contains("Ll");
    if digits.is_empty() || !valid_suffixes.contains(&suffix_lower.as_str()) || mixed_ll {
        return Err("an integer literal (digits, then `u`, `l` or `ll`)");
    }
    let value = u64::from_str_radix(digits, radix).map_err(|_| "an integer that fits in 64 bits")?;
    let unsigned = suffix_lower.contains('u') || value > i64::MAX as u64;
    Ok(Value { bits: value, unsigned })
}

struct Parser {
    tokens: Vec<(Tok, usize)>,
    at: usize,
    end: usize,
    depth: usize,
    /// `?:` operators being read, one inside another.
    conditionals: usize,
    /// Inside an operand that is not evaluated (the right of `0 &&`, say): no arithmetic errors.
    dead: usize,
}

/// Binary operators by precedence, loosest first (`&&` and `||` are handled apart, for their
/// short circuit).
const LEVELS: [&[&str]; 8] = [
    &["|"],
    &["^"],
    &["&"],
    &["==", "!="],
    &["<", ">", "<=", ">="],
    &["<<", ">>"],
    &["+", "-"],
    &["*", "/", "%"],
];

impl Parser {
    fn offset(&self) -> usize {
        self.tokens.get(self.at).map_or(self.end, |(_, o)| *o)
    }

    fn peek(&self, op: &str) -> bool {
        matches!(self.tokens.get(self.at), Some((Tok::Op(o), _)) if o == op)
    }

    fn eat(&mut self, op: &str) -> bool {
        let hit = self.peek(op);
        self.at += usize::from(hit);
        hit
    }

    /// Parses an operand, evaluated or not.
    fn operand_of(
        &mut self,
        evaluated: bool,
        parse: fn(&mut Parser) -> Result<Value, ExprError>,
    ) -> Result<Value, ExprError> {
        self.dead += usize::from(!evaluated);
        let value = parse(self);
        self.dead -= usize::from(!evaluated);
        value
    }

    /// `a, b` is `b` (gcc accepts the comma operator in `#if`; C89 leaves it out).
    fn comma(&mut self) -> Result<Value, ExprError> {
        let mut value = self.conditional()?;
        while self.eat(",") {
            value = self.conditional()?;
        }
        Ok(value)
    }

    fn conditional(&mut self) -> Result<Value, ExprError> {
        let condition = self.logical_or()?;
        if !self.eat("?") {
            return Ok(condition);
        }
        if self.conditionals >= MAX_CONDITIONALS {
            let limit = "at most 256 `?:` nested in one another (kiln's limit)";
            return Err(ExprError::NestedTooDeep { offset: self.offset(), limit });
        }
        self.conditionals += 1;
        let branches = self.branches(condition);
        self.conditionals -= 1;
        let (then, otherwise) = branches?;
        // The result has the common type of both branches, evaluated or not.
        let unsigned = then.unsigned || otherwise.unsigned;
        let chosen = if condition.is_true() { then } else { otherwise };
        Ok(Value { bits: chosen.bits, unsigned })
    }

    /// The two operands after a `?`.
    fn branches(&mut self, condition: Value) -> Result<(Value, Value), ExprError> {
        let then = self.operand_of(condition.is_true(), Parser::comma)?;
        if !self.eat(":") {
            return Err(ExprError::Malformed { offset: self.offset(), expected: "`:`" });
        }
        let otherwise = self.operand_of(!condition.is_true(), Parser::conditional)?;
        Ok((then, otherwise))
    }

    fn logical_or(&mut self) -> Result<Value, ExprError> {
        let mut left = self.logical_and()?;
        while self.eat("||") {
            let right = self.operand_of(!left.is_true(), Parser::logical_and)?;
            left = Value::truth(left.is_true() || right.is_true());
        }
        Ok(left)
    }

    fn logical_and(&mut self) -> Result<Value, ExprError> {
        let mut left = self.binary(0)?;
        while self.eat("&&") {
            let right = self.operand_of(left.is_true(), |p| p.binary(0))?;
            left = Value::truth(left.is_true() && right.is_true());
        }
        Ok(left)
    }

    fn binary(&mut self, level: usize) -> Result<Value, ExprError> {
        if level == LEVELS.len() {
            return self.unary();
        }
        let mut left = self.binary(level + 1)?;
        'outer: loop {
            for op in LEVELS[level] {
                let offset = self.offset();
                if self.eat(op) {
                    let right = self.binary(level + 1)?;
                    left = self.apply(op, left, right, offset)?;
                    continue 'outer;
                }
            }
            return Ok(left);
        }
    }

    fn apply(&self, op: &str, left: Value, right: Value, offset: usize) -> Result<Value, ExprError> {
        let live = self.dead == 0;
        if op == "<<" || op == ">>" {
            // The count must be 0 to 63; the result has the left operand's type.
            let count = right.bits;
            let negative = !right.unsigned && right.as_signed() < 0;
            if negative || count >= 64 {
                if live {
                    let count =
                        if right.unsigned { count.to_string() } else { right.as_signed().to_string() };
                    return Err(ExprError::InvalidShift { offset, count });
                }
                return Ok(Value { bits: 0, unsigned: left.unsigned });
            }
            let bits = match (op, left.unsigned) {
                ("<<", _) => left.bits << count,
                (_, true) => left.bits >> count,
                _ => (left.as_signed() >> count) as u64,
            };
            return Ok(Value { bits, unsigned: left.unsigned });
        }
        // The usual arithmetic conversions: unsigned if either is.
        let unsigned = left.unsigned || right.unsigned;
        let (a, b) = (left.bits, right.bits);
        let (sa, sb) = (a as i64, b as i64);
        let compare = |ordering: std::cmp::Ordering| {
            if unsigned { a.cmp(&b) == ordering } else { sa.cmp(&sb) == ordering }
        };
        let value = |bits: u64| Value { bits, unsigned };
        Ok(match op {
            "|" => value(a | b),
            "^" => value(a ^ b),
            "&" => value(a & b),
            "==" => Value::truth(a == b),
            "!=" => Value::truth(a != b),
            "<" => Value::truth(compare(std::cmp::Ordering::Less)),
            ">" => Value::truth(compare(std::cmp::Ordering::Greater)),
            "<=" => Value::truth(!compare(std::cmp::Ordering::Greater)),
            ">=" => Value::truth(!compare(std::cmp::Ordering::Less)),
            "+" => value(a.wrapping_add(b)),
            "-" => value(a.wrapping_sub(b)),
            "*" => value(a.wrapping_mul(b)),
            _ if b == 0 => {
                if live {
                    return Err(ExprError::DivisionByZero { offset });
                }
                value(0)
            }
            "/" if unsigned => value(a / b),
            "/" => value(sa.wrapping_div(sb) as u64),
            _ if unsigned => value(a % b),
            _ => value(sa.wrapping_rem(sb) as u64),
        })
    }

    /// Prefix operators, then a number or a parenthesised expression. The operators are read in
    /// a loop and applied innermost first, so a long run of them needs no stack.
    fn unary(&mut self) -> Result<Value, ExprError> {
        let mut operators = Vec::new();
        while let Some(op) = ["!", "-", "+", "~"].into_iter().find(|op| self.eat(op)) {
            operators.push(op);
        }
        let mut value = self.primary()?;
        for op in operators.into_iter().rev() {
            value = match op {
                "!" => Value::truth(!value.is_true()),
                "-" => Value { bits: value.bits.wrapping_neg(), ..value },
                "~" => Value { bits: !value.bits, ..value },
                _ => value,
            };
        }
        Ok(value)
    }

    fn primary(&mut self) -> Result<Value, ExprError> {
        if self.eat("(") {
            if self.depth >= MAX_NESTING {
                let limit = "at most 64 nested parentheses (kiln's limit; C guarantees 63)";
                return Err(ExprError::NestedTooDeep { offset: self.offset(), limit });
            }
            self.depth += 1;
            let value = self.comma();
            self.depth -= 1;
            let value = value?;
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
    use crate::preprocess::macros::MacroDef;

    fn eval(text: &str) -> Result<bool, ExprError> {
        let object = MacroDef::object;
        let (params, body) =
            (vec!["a".to_string(), "b".to_string()], crate::preprocess::macros::lex_body("((a) + (b))"));
        let macros: crate::preprocess::macros::Macros = [
            ("ONE", object("1")),
            ("EMPTY", object("")),
            ("MAX_DIRECTIONAL_LIGHT_COUNT", object("4")),
            ("TWICE", object("(MAX_DIRECTIONAL_LIGHT_COUNT * 2)")),
            ("SELF", object("SELF + 1")),
            ("PING", object("PONG")),
            ("PONG", object("PING")),
            ("CAFÉ", object("2")),
            ("ADD", MacroDef::new(Some(&params), false, "((a) + (b))", &body, None)),
        ]
        .into_iter()
        .collect();
        let mut hides = crate::preprocess::macros::HideSets::new();
        let mut expander = Expander::new(&macros, &mut hides);
        evaluate(text, &mut expander)
    }

    #[test]
    fn c_arithmetic_and_precedence() {
        assert_eq!(eval("1 + 2 * 3 == 7"), Ok(true));
        assert_eq!(eval("(1 + 2) * 3 == 9"), Ok(true));
        assert_eq!(eval("7 / 2 + 7 % 2 == 4"), Ok(true));
        assert_eq!(eval("1 < 2 == 1"), Ok(true));
        assert_eq!(eval("!0 && !!5 || 0"), Ok(true));
        assert_eq!(eval("-3 + +3 - ~0 == 1"), Ok(true));
        assert_eq!(eval("(1 << 4 | 0x0F & 3 ^ 1) == 18"), Ok(true));
        assert_eq!(eval("(0 ? 10 : 1 ? 20 : 30) == 20"), Ok(true));
        assert_eq!(eval("010 + 1u + 2L + 0b11 == 14"), Ok(true));
    }

    #[test]
    fn unsigned_arithmetic_follows_the_usual_conversions() {
        assert_eq!(eval("-1 < 0u"), Ok(false));
        assert_eq!(eval("-1 < 0"), Ok(true));
        assert_eq!(eval("(1 ? -1 : 0u) > 0"), Ok(true), "the branches' common type is unsigned");
        assert_eq!(eval("0xFFFFFFFFFFFFFFFF == -1"), Ok(true));
        assert_eq!(eval("0x8000000000000000 > 0"), Ok(true), "too large for intmax_t: unsigned");
        assert_eq!(eval("18446744073709551615u / 2 == 9223372036854775807"), Ok(true));
        assert_eq!(eval("-1 >> 1 == -1"), Ok(true), "signed shifts are arithmetic");
        assert_eq!(eval("-1u >> 63 == 1"), Ok(true));
        assert!(eval("18446744073709551616").is_err(), "past uintmax_t");
    }

    #[test]
    fn operands_not_evaluated_are_not_checked() {
        assert_eq!(eval("1 || 1/0"), Ok(true));
        assert_eq!(eval("0 && 1 % 0"), Ok(false));
        assert_eq!(eval("1 ? 2 : 1/0"), Ok(true));
        assert_eq!(eval("0 && (1 << 64)"), Ok(false));
        assert_eq!(eval("0 || 1/0"), Err(ExprError::DivisionByZero { offset: 6 }));
    }

    #[test]
    fn c_token_rules() {
        for refused in ["--1", "++1", "1uu", "1LLL", "1lL", "1.5", "1e3", "08", "\"s\""] {
            assert!(matches!(eval(refused), Err(ExprError::Malformed { .. })), "{refused}");
        }
        assert_eq!(eval("- -1 == 1"), Ok(true));
        assert_eq!(eval(&format!("{}1 == 1", "- ".repeat(32))), Ok(true), "32 unary minus signs");
        assert_eq!(eval("1uLL + 2LLu + 3Ul == 6"), Ok(true));
    }

    #[test]
    fn shifts_out_of_range_are_errors() {
        assert_eq!(eval("1 << 64"), Err(ExprError::InvalidShift { offset: 2, count: "64".into() }));
        assert_eq!(eval("1 >> -1"), Err(ExprError::InvalidShift { offset: 2, count: "-1".into() }));
        assert_eq!(eval("(1 << 63) < 0"), Ok(true));
    }

    #[test]
    fn macros_and_defined() {
        assert_eq!(eval("defined(ONE) && defined EMPTY"), Ok(true));
        assert_eq!(eval("defined(MISSING)"), Ok(false));
        assert_eq!(eval("MISSING + 1"), Ok(true), "unknown names are 0");
        assert_eq!(eval("TWICE == 8"), Ok(true));
        assert_eq!(eval("MAX_DIRECTIONAL_LIGHT_COUNT > 3"), Ok(true));
        assert_eq!(eval("SELF == 1"), Ok(true), "self-reference stops expanding");
        assert_eq!(eval("PING"), Ok(false), "mutual recursion stops expanding");
        assert_eq!(eval("CAFÉ == 2"), Ok(true), "non-ASCII names");
        assert_eq!(eval("ADD(ONE, 2) == 3"), Ok(true), "function-like macros");
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
        assert!(matches!(eval("1 @ 2"), Err(ExprError::Malformed { offset: 2, .. })));
        assert!(matches!(eval("defined"), Err(ExprError::Malformed { offset: 0, .. })));
        assert!(matches!(eval("defined(ONE"), Err(ExprError::Malformed { .. })));
        assert!(matches!(eval("EMPTY"), Err(ExprError::Malformed { .. })), "an empty macro leaves nothing");
    }

    #[test]
    fn the_comma_operator_gives_its_right_operand() {
        assert_eq!(eval("(0, 1)"), Ok(true));
        assert_eq!(eval("1 ? 0, 0 : 1"), Ok(false));
    }

    #[test]
    fn deep_nesting_is_refused() {
        let deep = format!("{}1{}", "(".repeat(10_000), ")".repeat(10_000));
        assert!(matches!(eval(&deep), Err(ExprError::NestedTooDeep { .. })));
        // Unary operators count for nothing: C's limit is on parentheses.
        assert_eq!(eval(&format!("{}1", "!".repeat(10_000))), Ok(true));
        assert_eq!(eval(&format!("{}1", "- ".repeat(10_001))), Ok(true));
        let fine = format!("{}1{}", "(".repeat(60), ")".repeat(60));
        assert_eq!(eval(&fine), Ok(true));
        // `?:` chains, either way, past 256: refused, not a stack overflow.
        let chain = format!("{}1", "0 ? 0 : ".repeat(30_000));
        assert!(matches!(eval(&chain), Err(ExprError::NestedTooDeep { .. })));
        let nested = format!("{}1{}", "1 ? ".repeat(30_000), " : 0".repeat(30_000));
        assert!(matches!(eval(&nested), Err(ExprError::NestedTooDeep { .. })));
        assert_eq!(eval(&format!("{}1", "0 ? 0 : ".repeat(200))), Ok(true));
    }

    proptest::proptest! {
        #[test]
        fn arbitrary_expressions_never_panic(text in "[0-9a-zA-Z_ ()+*/%!~&|^<>=?:,-]{0,60}") {
            let _ = eval(&text);
        }
    }

    #[test]
    fn overflow_wraps_instead_of_panicking() {
        assert_eq!(eval("9223372036854775807 + 1 < 0"), Ok(true));
        assert_eq!(eval("(0 - 9223372036854775807 - 1) / -1 < 0"), Ok(true));
    }
}
