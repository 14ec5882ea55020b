//! The progress bar of the study commands (stderr; indicatif hides it when stderr is not a
//! terminal).

use fixedfunc::study::Progress;
use indicatif::{ProgressBar, ProgressStyle};

/// A bar that follows a study's [`Progress`] reports.
pub struct StudyBar(ProgressBar);

impl StudyBar {
    pub fn new() -> StudyBar {
        let bar = ProgressBar::new(1);
        bar.set_style(
            ProgressStyle::with_template("[{bar:32}] {pos}/{len} {elapsed_precise} {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_bar())
                .progress_chars("=> "),
        );
        StudyBar(bar)
    }

    pub fn update(&self, p: Progress) {
        self.0.set_length(p.total);
        self.0.set_position(p.done);
        self.0.set_message(p.what);
    }

    pub fn finish(&self) {
        self.0.finish_and_clear();
    }
}
