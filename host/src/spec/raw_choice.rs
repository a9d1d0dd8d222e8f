//! A `[map]` value the design search may choose, as TOML spells it: one number, a list, or `"auto"`,
//! read by hand for messages that say what is expected.

use serde::Deserialize;

/// A `[map]` value the design search may choose: one number, a list of candidates, or `"auto"` (the
/// search's default candidates).
#[derive(Clone, Debug, PartialEq)]
pub(super) enum RawChoice<T> {
    One(T),
    List(Vec<T>),
    Auto,
}

/// A number TOML may spell as an integer or a float, read as `Self`.
pub(super) trait RawNumber: Sized {
    const EXPECTING: &'static str;
    fn from_i64(v: i64) -> Option<Self>;
    fn from_f64(v: f64) -> Option<Self>;
}

impl RawNumber for usize {
    const EXPECTING: &'static str = "a whole number ≥ 0, a list of them, or \"auto\"";
    fn from_i64(v: i64) -> Option<Self> {
        usize::try_from(v).ok()
    }
    fn from_f64(_: f64) -> Option<Self> {
        None
    }
}

impl RawNumber for f64 {
    const EXPECTING: &'static str = "a number, a list of numbers, or \"auto\"";
    fn from_i64(v: i64) -> Option<Self> {
        Some(v as f64)
    }
    fn from_f64(v: f64) -> Option<Self> {
        Some(v)
    }
}

/// By hand, for messages that say what is expected (an untagged enum says "did not match any variant").
impl<'de, T: RawNumber> Deserialize<'de> for RawChoice<T> {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor<T>(std::marker::PhantomData<T>);
        impl<T: RawNumber> Visitor<T> {
            fn one<E: serde::de::Error>(value: Option<T>, shown: &dyn std::fmt::Display) -> Result<T, E> {
                value.ok_or_else(|| E::custom(format!("`{shown}` is not {}", T::EXPECTING)))
            }
        }
        impl<'de, T: RawNumber> serde::de::Visitor<'de> for Visitor<T> {
            type Value = RawChoice<T>;

            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str(T::EXPECTING)
            }

            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<RawChoice<T>, E> {
                Self::one(T::from_i64(v), &v).map(RawChoice::One)
            }

            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<RawChoice<T>, E> {
                Self::one(i64::try_from(v).ok().and_then(T::from_i64), &v).map(RawChoice::One)
            }

            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<RawChoice<T>, E> {
                Self::one(T::from_f64(v), &v).map(RawChoice::One)
            }

            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<RawChoice<T>, E> {
                match v {
                    "auto" => Ok(RawChoice::Auto),
                    _ => Err(E::custom(format!("\"{v}\" is not {}", T::EXPECTING))),
                }
            }

            fn visit_seq<A: serde::de::SeqAccess<'de>>(self, mut seq: A) -> Result<RawChoice<T>, A::Error> {
                let mut values = Vec::new();
                while let Some(element) = seq.next_element::<RawChoice<T>>()? {
                    match element {
                        RawChoice::One(v) => values.push(v),
                        _ => return Err(serde::de::Error::custom("a list of candidates holds numbers only")),
                    }
                }
                Ok(RawChoice::List(values))
            }
        }
        deserializer.deserialize_any(Visitor(std::marker::PhantomData))
    }
}

// ---------------------------------------------------------------------------------------------------
