//! The speed-against-error picture `kiln accuracy --plot` writes: GPU time per evaluation against
//! worst relative error (both log scale), one point per formulation, the Pareto front drawn, the
//! adapter named. SVG through plotters (text as SVG text: no font files needed), and PNG by
//! rasterising that SVG with resvg (text in the system's fonts).

use super::{Formulation, Found, Row, Timing};
use plotters::prelude::*;

/// One formulation in the picture.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// Its name in the report.
    pub name: String,
    /// GPU time per evaluation of one light, in nanoseconds.
    pub nanoseconds: f64,
    /// Its worst max relative error over the chosen hard-case sets.
    pub worst_chosen: f64,
    /// The worst relative error the search found, if it ran.
    pub worst_found: Option<f64>,
}

/// The points of a report: each formulation that was timed, with its worst errors.
pub fn points(rows: &[Row], timings: &[Timing], found: &[(Formulation, Found)]) -> Vec<Point> {
    Formulation::ALL
        .iter()
        .filter_map(|formulation| {
            let name = formulation.name();
            let prefix = format!("{name}: one light");
            let nanoseconds =
                timings.iter().find(|t| t.what.starts_with(&prefix))?.nanoseconds_per_evaluation;
            let worst_chosen = rows
                .iter()
                .filter(|r| r.formulation == name)
                .map(|r| r.stats.max_relative)
                .fold(0.0f64, f64::max);
            let worst_found = found.iter().find(|(f, _)| f == formulation).map(|(_, found)| found.error);
            Some(Point { name: name.to_string(), nanoseconds, worst_chosen, worst_found })
        })
        .collect()
}

/// The points no other beats in both time and worst error on the chosen sets (at least as good
/// in both, better in one), fastest first.
pub fn pareto_front(points: &[Point]) -> Vec<usize> {
    let dominated = |p: &Point| {
        points.iter().any(|q| {
            q.nanoseconds <= p.nanoseconds
                && q.worst_chosen <= p.worst_chosen
                && (q.nanoseconds < p.nanoseconds || q.worst_chosen < p.worst_chosen)
        })
    };
    let mut front: Vec<usize> = (0..points.len()).filter(|&i| !dominated(&points[i])).collect();
    front.sort_by(|&a, &b| points[a].nanoseconds.total_cmp(&points[b].nanoseconds));
    front
}

/// The picture as SVG text.
pub fn svg(adapter: &str, points: &[Point]) -> Result<String, String> {
    let mut text = String::new();
    {
        let area = SVGBackend::with_string(&mut text, (800, 520)).into_drawing_area();
        area.fill(&WHITE).map_err(|e| e.to_string())?;
        let errors = points.iter().flat_map(|p| std::iter::once(p.worst_chosen).chain(p.worst_found));
        let (low, high) = errors.fold((f64::INFINITY, 0.0f64), |(lo, hi), e| (lo.min(e), hi.max(e)));
        let times = points.iter().map(|p| p.nanoseconds);
        let (fast, slow) = times.fold((f64::INFINITY, 0.0f64), |(lo, hi), t| (lo.min(t), hi.max(t)));
        let (low, high) = ((low.max(1e-12) / 4.0), high.max(low * 10.0) * 4.0);

        let mut chart = ChartBuilder::on(&area)
            .caption(format!("Speed against error: {adapter}"), ("sans-serif", 20))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(72)
            .build_cartesian_2d((fast / 1.5..slow * 3.0).log_scale(), (low..high).log_scale())
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .x_desc("GPU time per evaluation, one light (ns, log scale)")
            // A range within one decade has no log-scale ticks: each point's label gives its time.
            .x_labels(12)
            .x_label_formatter(&|x| format!("{x:.2e}"))
            .y_desc("worst max relative error")
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()
            .map_err(|e| e.to_string())?;
        let front: Vec<(f64, f64)> = pareto_front(points)
            .into_iter()
            .map(|i| (points[i].nanoseconds, points[i].worst_chosen))
            .collect();
        chart
            .draw_series(LineSeries::new(front, BLUE.stroke_width(2)))
            .map_err(|e| e.to_string())?
            .label("Pareto front (chosen hard cases)")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE.stroke_width(2)));
        chart
            .draw_series(points.iter().map(|p| {
                // Labels alternate above and below in order of time, so that close points stay
                // readable.
                let rank = points.iter().filter(|q| q.nanoseconds < p.nanoseconds).count();
                let offset = if rank % 2 == 0 { (8, -18) } else { (8, 6) };
                EmptyElement::at((p.nanoseconds, p.worst_chosen))
                    + Circle::new((0, 0), 5, BLUE.filled())
                    + Text::new(format!("{} ({:.4} ns)", p.name, p.nanoseconds), offset, ("sans-serif", 14))
            }))
            .map_err(|e| e.to_string())?
            .label("worst on the chosen hard cases")
            .legend(|(x, y)| Circle::new((x + 10, y), 5, BLUE.filled()));
        chart
            .draw_series(
                points.iter().filter_map(|p| {
                    Some(Circle::new((p.nanoseconds, p.worst_found?), 5, RED.stroke_width(2)))
                }),
            )
            .map_err(|e| e.to_string())?
            .label("worst found by search")
            .legend(|(x, y)| Circle::new((x + 10, y), 5, RED.stroke_width(2)));
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .position(SeriesLabelPosition::MiddleLeft)
            .draw()
            .map_err(|e| e.to_string())?;
        area.present().map_err(|e| e.to_string())?;
    }
    Ok(text)
}

/// The picture for a file at `path`: PNG when its name ends in `.png`, else SVG.
pub fn picture_for(path: &std::path::Path, adapter: &str, points: &[Point]) -> Result<Vec<u8>, String> {
    let svg = svg(adapter, points)?;
    match path.extension().is_some_and(|e| e.eq_ignore_ascii_case("png")) {
        true => png(&svg),
        false => Ok(svg.into_bytes()),
    }
}

/// The picture `svg` drew, as PNG bytes at twice its size. Text is set in a sans-serif font the
/// system has (DejaVu Sans or Liberation Sans where installed); with no font at all the PNG has
/// the axes, points and front without their words.
pub fn png(svg: &str) -> Result<Vec<u8>, String> {
    use resvg::{tiny_skia, usvg};
    let mut options = usvg::Options::default();
    let fonts = options.fontdb_mut();
    fonts.load_system_fonts();
    let families: Vec<String> =
        fonts.faces().filter_map(|face| face.families.first().map(|(name, _)| name.clone())).collect();
    let family = ["DejaVu Sans", "Liberation Sans"]
        .iter()
        .find(|wanted| families.iter().any(|f| f == *wanted))
        .map(|found| found.to_string())
        .or_else(|| families.first().cloned());
    if let Some(family) = family {
        fonts.set_sans_serif_family(family.clone());
        options.font_family = family;
    }
    let tree = usvg::Tree::from_str(svg, &options).map_err(|e| e.to_string())?;
    let size = tree.size().to_int_size();
    let mut pixmap = tiny_skia::Pixmap::new(size.width() * 2, size.height() * 2).ok_or("an empty picture")?;
    resvg::render(&tree, tiny_skia::Transform::from_scale(2.0, 2.0), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(name: &str, nanoseconds: f64, worst_chosen: f64) -> Point {
        Point { name: name.into(), nanoseconds, worst_chosen, worst_found: Some(worst_chosen * 10.0) }
    }

    #[test]
    fn the_front_keeps_what_nothing_beats_in_both() {
        let points = [
            point("seed", 2.0, 1e-2),
            point("stable", 2.6, 3e-6),
            point("f16", 20.0, 4e-3),
            point("ratio", 1.9, 3e-6),
        ];
        assert_eq!(pareto_front(&points), [3], "ratio is faster and as accurate as stable");
        let points = [point("seed", 2.0, 1e-2), point("stable", 2.6, 3e-6), point("f16", 3.4, 4e-3)];
        assert_eq!(pareto_front(&points), [0, 1]);
        let svg = svg("test adapter", &points).expect("draws");
        assert!(svg.starts_with("<svg") && svg.contains("test adapter") && svg.contains("stable"), "{svg}");
        assert_eq!(svg.matches("<circle").count(), 3 + 3 + 2, "points, found points and legend marks");

        // The PNG: twice the SVG's 800 x 520, a white page with the blue points and front on it.
        let png =
            picture_for(std::path::Path::new("speed.PNG"), "test adapter", &points).expect("rasterises");
        let picture = crate::preview::Picture::from_png(&png).expect("a PNG");
        assert_eq!((picture.width, picture.height), (1600, 1040));
        let rgba = &picture.rgba;
        let blue = rgba.chunks(4).filter(|p| p[2] > 200 && p[0] < 60 && p[1] < 60).count();
        let white = rgba.chunks(4).filter(|p| p[..3] == [255, 255, 255]).count();
        assert!(blue > 500 && white > rgba.len() / 4 / 2, "blue {blue}, white {white}");
    }
}
