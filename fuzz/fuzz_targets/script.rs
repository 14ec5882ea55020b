//! The GL-call script reader: `ff::script::parse` on any text. The property: no panic, no
//! abort, no hang; an error is an `Err` whose Display starts `line N:` with N a line of the
//! text; a script that parses prints (`print`) and the printed text parses again.

#![no_main]

use fixedfunc::ff::script::{parse, print};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match parse(&text) {
        Ok(commands) => {
            let printed = print(&commands);
            if let Err(e) = parse(&printed) {
                panic!("the printed script does not parse again: {e}\n{printed}");
            }
        }
        Err(e) => {
            let message = e.to_string();
            let line: usize = message
                .strip_prefix("line ")
                .and_then(|rest| rest.split(':').next())
                .and_then(|n| n.parse().ok())
                .unwrap_or_else(|| panic!("`{message}` does not start with `line N:`"));
            let lines = text.matches('\n').count() + 1;
            assert!(
                (1..=lines).contains(&line),
                "`{message}`: the text has {lines} lines"
            );
        }
    }
});
