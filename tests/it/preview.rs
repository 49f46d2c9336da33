//! `kiln preview`: a material drawn through the run time, checked against the picture in the
//! docs (a golden image with a tolerance), against the f64 reference pixel by pixel, across
//! languages (the HLSL Lit shader draws as the WGSL one), and with a shader of Unity's own.

use crate::support::{self, root};
use kiln::preview::{self, Picture};
use kiln::reference::{self as r, camera::Basis};
use std::path::Path;

/// The picture docs/first-shader.md shows, which this test pins.
const DOCS_PICTURE: &str = "docs/images/preview-LitOpaque.png";

/// A fixture project's material drawn at `size`, or `None` (skipped) without an adapter.
fn drawn(project: &Path, material: &str, size: u32, test: &str) -> Option<preview::Preview> {
    support::gpu(test)?;
    let output = tempfile::tempdir().expect("temp dir");
    support::build_without_errors(project, Some(output.path()), kiln::config::VariantSelection::Used);
    let library = kiln::runtime::Library::open(output.path()).expect("the build opens");
    Some(preview::draw(library, material, size).expect("the preview draws"))
}

fn pixel(picture: &Picture, x: u32, y: u32) -> [u8; 4] {
    let at = ((y * picture.width + x) * 4) as usize;
    picture.rgba[at..at + 4].try_into().expect("four bytes")
}

/// The share of pixels whose channels all lie within `tolerance` of the other picture's, and the
/// largest difference.
fn agreement(a: &Picture, b: &Picture, tolerance: u8) -> (f64, u8) {
    assert_eq!((a.width, a.height), (b.width, b.height));
    let mut within = 0;
    let mut largest = 0;
    for (p, q) in a.rgba.chunks_exact(4).zip(b.rgba.chunks_exact(4)) {
        let worst = p.iter().zip(q).map(|(x, y)| x.abs_diff(*y)).max().unwrap_or(0);
        largest = largest.max(worst);
        within += usize::from(worst <= tolerance);
    }
    (within as f64 / (a.rgba.len() / 4) as f64, largest)
}

#[test]
fn a_material_s_preview_is_the_picture_the_docs_show() {
    let Some(drawn) = drawn(&root().join("fixtures/project"), "LitOpaque", 256, "preview golden") else {
        return;
    };
    assert_eq!((drawn.shader.as_str(), drawn.pass), ("Custom RP/Lit", 0));
    assert!(drawn.notes.is_empty(), "{:?}", drawn.notes);
    let golden = root().join(DOCS_PICTURE);
    if std::env::var_os("UPDATE_EXPECT").is_some() {
        std::fs::write(&golden, drawn.picture.png().expect("encodes")).expect("write the golden");
    }
    let want = Picture::from_png(&std::fs::read(&golden).expect("the docs' picture")).expect("decodes");
    // Another rasteriser (or llvmpipe release) may round a few edge pixels otherwise.
    let (share, largest) = agreement(&drawn.picture, &want, 2);
    assert!(
        share >= 0.995,
        "{:.2}% of pixels within 2/255 of {DOCS_PICTURE} (largest {largest})",
        share * 100.0
    );
    let docs = std::fs::read_to_string(root().join("docs/first-shader.md")).expect("docs");
    assert!(
        docs.contains("images/preview-LitOpaque.png") && docs.contains("preview LitOpaque fixtures/project")
    );
}

/// Where the ray through the centre of pixel (x, y) meets the unit sphere, if it does.
fn sphere_hit(size: u32, x: u32, y: u32) -> Option<(r::Vec3, r::Vec3)> {
    let (eye, target, tan_half_fov) = preview::CAMERA;
    let basis = Basis::looking_at(eye, target);
    let ndc = |p: u32| (f64::from(p) + 0.5) / f64::from(size) * 2.0 - 1.0;
    let ray = r::normalize(r::add(
        basis.forward,
        r::add(r::scale(basis.right, ndc(x) * tan_half_fov), r::scale(basis.up, -ndc(y) * tan_half_fov)),
    ));
    let b = r::dot(eye, ray);
    let disc = b * b - (r::dot(eye, eye) - 1.0);
    let t = (disc > 0.0).then(|| -b - disc.sqrt())?;
    let point = r::add(eye, r::scale(ray, t));
    Some((point, r::normalize(r::sub(eye, point))))
}

#[test]
fn the_lit_sphere_s_pixels_are_the_f64_reference_s() {
    let size = 128;
    let Some(drawn) = drawn(&root().join("fixtures/project"), "LitOpaque", size, "preview reference") else {
        return;
    };
    let lights: Vec<r::Light> =
        preview::LIGHTS.iter().map(|(d, c)| r::Light { color: *c, direction: r::normalize(*d) }).collect();
    // LitOpaque: white, metallic 0, smoothness 0.5.
    let mut compared = 0;
    let mut worst = 0.0f64;
    for y in (0..size).step_by(2) {
        for x in (0..size).step_by(2) {
            // Well inside the silhouette, where a tessellated sphere and the exact one agree.
            let inner = [(0, 0), (2, 0), (0, 2), (2, 2)].iter().all(|(dx, dy)| {
                sphere_hit(size, (x + dx).min(size - 1), (y + dy).min(size - 1)).is_some()
                    && sphere_hit(size, x.saturating_sub(2), y.saturating_sub(2)).is_some()
            });
            let Some((normal, view_direction)) = sphere_hit(size, x, y).filter(|_| inner) else { continue };
            if normal[1] < -0.2 {
                continue; // The plane hides the sphere's lower part.
            }
            let surface = r::Surface {
                normal,
                view_direction,
                color: [1.0; 3],
                alpha: 1.0,
                metallic: 0.0,
                smoothness: 0.5,
            };
            let want = r::lighting(&surface, &r::get_brdf(&surface, false), &lights);
            let got = pixel(&drawn.picture, x, y);
            for k in 0..3 {
                let error = (f64::from(got[k]) / 255.0 - want[k].clamp(0.0, 1.0)).abs();
                worst = worst.max(error);
            }
            compared += 1;
        }
    }
    assert!(compared > 500, "{compared} pixels compared");
    // 8-bit rounding is 0.5/255; the tessellation's normals (64 x 128) and f32 add the rest.
    eprintln!("preview against the reference: worst {:.2}/255 over {compared} pixels", worst * 255.0);
    assert!(worst <= 1.5 / 255.0, "worst {:.2}/255 over {compared} pixels", worst * 255.0);
}

#[test]
fn the_hlsl_lit_shader_previews_as_the_wgsl_one_does() {
    for material in ["LitOpaque", "LitClip", "LitTransparent"] {
        let test = "preview HLSL against WGSL";
        let Some(wgsl) = drawn(&root().join("fixtures/project"), material, 128, test) else { return };
        let Some(hlsl) = drawn(&root().join("fixtures/hlsl_lit"), material, 128, test) else { return };
        assert_eq!(wgsl.keywords, hlsl.keywords, "{material}");
        let (share, largest) = agreement(&wgsl.picture, &hlsl.picture, 1);
        assert!(share == 1.0, "{material}: {:.3}% within 1/255, largest {largest}", share * 100.0);
    }
}

/// A project of Unity's `Unlit/Color` (2019.4, MIT) with its own CGIncludes and one material.
fn unity_unlit_project(dir: &Path, color: [f64; 4]) {
    let unity = root().join("tests/corpus/unity/Unity-Built-in-Shaders");
    std::fs::create_dir_all(dir.join("shaders")).expect("dir");
    std::fs::create_dir_all(dir.join("materials")).expect("dir");
    std::fs::create_dir_all(dir.join("CGIncludes")).expect("dir");
    std::fs::copy(
        unity.join("DefaultResourcesExtra/Unlit/Unlit-Color.shader"),
        dir.join("shaders/Unlit-Color.shader"),
    )
    .expect("copy the shader");
    for entry in std::fs::read_dir(unity.join("CGIncludes")).expect("CGIncludes") {
        let path = entry.expect("entry").path();
        std::fs::copy(&path, dir.join("CGIncludes").join(path.file_name().expect("name"))).expect("copy");
    }
    std::fs::write(
        dir.join("kiln.toml"),
        "shaders = [\"shaders\"]\nmaterials = [\"materials\"]\ninclude_paths = [\"CGIncludes\"]\n",
    )
    .expect("kiln.toml");
    let [red, green, blue, alpha] = color;
    std::fs::write(
        dir.join("materials/Sky.mat"),
        format!("shader = \"Unlit/Color\"\n[properties]\n_Color = [{red}, {green}, {blue}, {alpha}]\n"),
    )
    .expect("material");
}

#[test]
fn unity_s_own_unlit_color_previews_its_colour_on_the_sphere_and_the_plane() {
    let dir = tempfile::tempdir().expect("temp dir");
    let color = [0.2, 0.5, 0.9, 1.0];
    unity_unlit_project(dir.path(), color);
    let Some(drawn) = drawn(dir.path(), "Sky", 64, "preview of a Unity shader") else { return };
    // Its UnityCG.cginc reads the frame's and object's matrices under Unity's names.
    let want = color.map(|c| c * 255.0);
    let near =
        |got: [u8; 4], want: [f64; 4]| got.iter().zip(want).all(|(g, w)| (f64::from(*g) - w).abs() <= 1.0);
    let sphere = pixel(&drawn.picture, 32, 20);
    let plane = pixel(&drawn.picture, 32, 60);
    let background = pixel(&drawn.picture, 2, 2);
    assert!(near(sphere, want), "sphere {sphere:?}");
    assert!(near(plane, want), "plane {plane:?}");
    assert!(near(
        background,
        [preview::BACKGROUND[0], preview::BACKGROUND[1], preview::BACKGROUND[2], 1.0].map(|c| c * 255.0)
    ));
    // The members of Unity's blocks it leaves at zero are named, never silently.
    assert!(drawn.notes.iter().any(|n| n.contains("unity_LODFade")), "{:?}", drawn.notes);
}

/// `kiln preview`, with the user's cache in `cache`.
fn preview_command(folder: &Path, cache: &Path, args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
        .arg("preview")
        .args(args)
        .current_dir(folder)
        .env("NO_COLOR", "1")
        .env("XDG_CACHE_HOME", cache)
        .output()
        .expect("kiln runs")
}

#[test]
fn kiln_preview_writes_the_png_and_names_a_material_it_does_not_have() {
    if support::gpu("kiln preview").is_none() {
        return;
    }
    let (work, cache) = (tempfile::tempdir().expect("temp"), tempfile::tempdir().expect("temp"));
    let project = root().join("fixtures/project");
    let project = project.to_str().expect("utf-8");
    let out = preview_command(work.path(), cache.path(), &["LitClip", project, "--size", "48"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("drew LitClip (Custom RP/Lit, pass 0, _CLIPPING)"), "{stderr}");
    let written = Picture::from_png(&std::fs::read(work.path().join("LitClip.png")).expect("LitClip.png"))
        .expect("a PNG");
    assert_eq!((written.width, written.height), (48, 48));
    // The project's own output folder is left alone: the build went to the user's cache.
    assert!(std::fs::read_dir(cache.path().join("kiln/preview")).expect("the preview's build").count() == 1);

    let out = preview_command(work.path(), cache.path(), &["LitClips", project]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("no material `LitClips` in the build (did you mean `LitClip`?)"), "{stderr}");
    assert!(!work.path().join("LitClips.png").exists());

    // The listing of materials points at it.
    let listed = support::kiln(&["list", "--materials", project]);
    assert!(String::from_utf8_lossy(&listed.stdout).contains("kiln preview MATERIAL"));
}
