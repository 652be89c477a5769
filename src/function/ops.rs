//! The operators and float functions a function body may use, with their arithmetic: one
//! definition that the tree walk, constant folding and the compiled code all call.

/// One-operand operators and float functions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unary {
    Neg,
    /// `!a`: 1 where `a` is 0, else 0.
    Not,
    Abs,
    Sqrt,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sinh,
    Cosh,
    Tanh,
    Asinh,
    Acosh,
    Atanh,
    Exp,
    /// Natural logarithm.
    Ln,
    /// Base-10 logarithm (POV-Ray's `log`).
    Log,
    Floor,
    Ceil,
    /// Truncation towards zero.
    Int,
    Radians,
    Degrees,
}

/// Two-operand operators and float functions. Comparisons and logic give 1 or 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Binary {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
    Atan2,
    /// `mod(a, b)`: C's `fmod`, the sign of `a`.
    Mod,
    Min,
    Max,
}

fn truth(b: bool) -> f64 {
    if b {
        1.0
    } else {
        0.0
    }
}

impl Unary {
    /// The float function of this name taking one argument.
    pub fn named(name: &str) -> Option<Unary> {
        Some(match name {
            "abs" => Unary::Abs,
            "sqrt" => Unary::Sqrt,
            "sin" => Unary::Sin,
            "cos" => Unary::Cos,
            "tan" => Unary::Tan,
            "asin" => Unary::Asin,
            "acos" => Unary::Acos,
            "atan" => Unary::Atan,
            "sinh" => Unary::Sinh,
            "cosh" => Unary::Cosh,
            "tanh" => Unary::Tanh,
            "asinh" => Unary::Asinh,
            "acosh" => Unary::Acosh,
            "atanh" => Unary::Atanh,
            "exp" => Unary::Exp,
            "ln" => Unary::Ln,
            "log" => Unary::Log,
            "floor" => Unary::Floor,
            "ceil" => Unary::Ceil,
            "int" => Unary::Int,
            "radians" => Unary::Radians,
            "degrees" => Unary::Degrees,
            _ => return None,
        })
    }

    #[inline]
    pub fn apply(self, a: f64) -> f64 {
        match self {
            Unary::Neg => -a,
            Unary::Not => truth(a == 0.0),
            Unary::Abs => a.abs(),
            Unary::Sqrt => a.sqrt(),
            Unary::Sin => a.sin(),
            Unary::Cos => a.cos(),
            Unary::Tan => a.tan(),
            Unary::Asin => a.asin(),
            Unary::Acos => a.acos(),
            Unary::Atan => a.atan(),
            Unary::Sinh => a.sinh(),
            Unary::Cosh => a.cosh(),
            Unary::Tanh => a.tanh(),
            Unary::Asinh => a.asinh(),
            Unary::Acosh => a.acosh(),
            Unary::Atanh => a.atanh(),
            Unary::Exp => a.exp(),
            Unary::Ln => a.ln(),
            Unary::Log => a.log10(),
            Unary::Floor => a.floor(),
            Unary::Ceil => a.ceil(),
            Unary::Int => a.trunc(),
            Unary::Radians => a.to_radians(),
            Unary::Degrees => a.to_degrees(),
        }
    }
}

impl Binary {
    /// The float function of this name taking two arguments (`min` and `max` take more,
    /// folded left into pairs by the parser).
    pub fn named(name: &str) -> Option<Binary> {
        Some(match name {
            "atan2" => Binary::Atan2,
            "mod" => Binary::Mod,
            "pow" => Binary::Pow,
            "min" => Binary::Min,
            "max" => Binary::Max,
            _ => return None,
        })
    }

    #[inline]
    pub fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            Binary::Add => a + b,
            Binary::Sub => a - b,
            Binary::Mul => a * b,
            Binary::Div => a / b,
            Binary::Pow => a.powf(b),
            Binary::Lt => truth(a < b),
            Binary::Le => truth(a <= b),
            Binary::Gt => truth(a > b),
            Binary::Ge => truth(a >= b),
            Binary::Eq => truth(a == b),
            Binary::Ne => truth(a != b),
            Binary::And => truth(a != 0.0 && b != 0.0),
            Binary::Or => truth(a != 0.0 || b != 0.0),
            Binary::Atan2 => a.atan2(b),
            Binary::Mod => a % b,
            Binary::Min => a.min(b),
            Binary::Max => a.max(b),
        }
    }
}
