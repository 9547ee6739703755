//! The measurements as the terminal and the README show them (a Markdown
//! table), as a file keeps them (CSV), and the best of them (the Pareto
//! front).

use serde::Serialize;

use super::measure::Measurement;
use crate::bench::table::markdown;

/// The measurements as a Markdown table, for the terminal and the README.
pub fn table(measurements: &[Measurement]) -> String {
    let header = [
        "knob",
        "value",
        "time (s)",
        "rays",
        "RMSE",
        "PSNR (dB)",
        "max error",
        "pixels off > 1/255",
    ];
    markdown(header, measurements.iter().map(cells), 2)
}

/// The table's cells for one measurement.
fn cells(m: &Measurement) -> [String; 8] {
    let psnr = if m.psnr.is_finite() {
        format!("{:.1}", m.psnr)
    } else {
        "∞".to_owned()
    };
    [
        m.setting.knob.name().to_owned(),
        m.setting.value.clone(),
        format!("{:.4}", m.seconds),
        m.rays.to_string(),
        format!("{:.5}", m.rmse),
        psnr,
        format!("{:.4}", m.max_error),
        format!("{:.2}%", 100.0 * m.share_off),
    ]
}

/// One line of the CSV file: a measurement in full precision.
#[derive(Debug, Serialize)]
struct CsvRecord<'a> {
    knob: &'static str,
    value: &'a str,
    seconds: f64,
    rays: u64,
    rmse: f64,
    psnr_db: f64,
    max_error: f64,
    share_off_1_255: f64,
}

impl<'a> From<&'a Measurement> for CsvRecord<'a> {
    fn from(m: &'a Measurement) -> Self {
        CsvRecord {
            knob: m.setting.knob.name(),
            value: &m.setting.value,
            seconds: m.seconds,
            rays: m.rays,
            rmse: m.rmse,
            psnr_db: m.psnr,
            max_error: m.max_error,
            share_off_1_255: m.share_off,
        }
    }
}

/// The measurements as CSV: a header, then one line per setting, numbers in
/// full precision. An exact match has an infinite PSNR, written `inf`.
pub fn csv(measurements: &[Measurement]) -> String {
    let mut writer = csv::Writer::from_writer(Vec::new());
    for m in measurements {
        writer
            .serialize(CsvRecord::from(m))
            .expect("a record of plain fields always serialises into memory");
    }
    let bytes = writer.into_inner().expect("writing to memory cannot fail");
    String::from_utf8(bytes).expect("CSV of UTF-8 text is UTF-8")
}

/// The measurements on the Pareto front, fastest first: no other is both
/// faster and more accurate (those with zero error are the references, and
/// on it if fastest).
pub fn pareto(measurements: &[Measurement]) -> Vec<&Measurement> {
    let dominates = |o: &Measurement, m: &Measurement| {
        o.seconds <= m.seconds && o.rmse <= m.rmse && (o.seconds < m.seconds || o.rmse < m.rmse)
    };
    let mut front: Vec<&Measurement> = measurements
        .iter()
        .filter(|m| !measurements.iter().any(|o| dominates(o, m)))
        .collect();
    front.sort_by(|a, b| a.seconds.total_cmp(&b.seconds));
    front
}
