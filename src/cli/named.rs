//! Command-line values read through `vocab::Named`: the names a user types are the ones
//! the vocabulary defines (and scene files read), so no layer below `cli` derives a
//! command-line trait and no spelling is written twice.

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use fixedfunc::vocab::Named;

/// A clap value parser for a [`Named`] type: accepts exactly its names, lists them (with
/// their help) in `--help` and in the error for anything else.
pub fn named<T: Named + Send + Sync>() -> impl TypedValueParser<Value = T> {
    let values = T::all().into_iter().map(|v| {
        let value = PossibleValue::new(v.name());
        match v.help() {
            "" => value,
            help => value.help(help),
        }
    });
    PossibleValuesParser::new(values).map(|name: String| {
        T::from_name(&name).unwrap_or_else(|| unreachable!("clap accepted only the names of T"))
    })
}
