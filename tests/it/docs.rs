//! The docs as a new user reads them: a renderer crate assembled from `docs/renderer.md`'s code
//! blocks exactly as they stand, built by cargo (kiln as its build script and its run time) and
//! run on the GPU, drawing through the material layer with no layout or uniform code of its own;
//! the README's Rust blocks compiled in the same crate.

use crate::support::{cargo_scratch, root};
use std::path::Path;

/// The fenced code blocks of `language` in a Markdown text, in order.
fn code_blocks(markdown: &str, language: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    let mut current: Option<String> = None;
    for line in markdown.lines() {
        match (&mut current, line.trim_start().strip_prefix("```")) {
            (None, Some(info)) if info.trim() == language => current = Some(String::new()),
            (Some(_), Some("")) => blocks.extend(current.take()),
            (Some(block), _) => {
                block.push_str(line);
                block.push('\n');
            }
            _ => {}
        }
    }
    blocks
}

/// What the docs leave to the renderer: a device, the targets, a white texture, a camera and an
/// object (identity matrices: the triangle is given in clip space), a triangle facing the light,
/// and reading the pixel back. The docs' blocks go where `{...}` stand.
const HARNESS: &str = r#"
{generated_module}

fn device() -> (wgpu::Device, wgpu::Queue) {
    let adapter = kiln_runtime::adapter(wgpu::Backends::all()).expect("an adapter (lavapipe in CI)");
    pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default())).expect("a device")
}

fn texture(device: &wgpu::Device, format: wgpu::TextureFormat, usage: wgpu::TextureUsages) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: None,
        size: wgpu::Extent3d { width: 8, height: 8, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage,
        view_formats: &[],
    })
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (device, queue) = device();
    let (format, depth_format) = (wgpu::TextureFormat::Rgba8Unorm, wgpu::TextureFormat::Depth32Float);
    let white = texture(&device, format, wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST);
    queue.write_texture(white.as_image_copy(), &[255u8; 8 * 8 * 4], wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(32), rows_per_image: None }, white.size());
    let white_view = white.create_view(&Default::default());
    let identity = [[1.0f32, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    let (view_projection, object_to_world, world_to_object) = (identity, identity, identity);
    let eye = [0.0f32, 0.0, -5.0];

    {materials_to_bind_groups}

    {per_frame_and_per_object}

    // A triangle in clip space facing the camera (normal towards -z, as the light comes from).
    let vertex = |x: f32, y: f32| [x, y, 0.5, 0.0, 0.0, -1.0, 0.5, 0.5];
    let triangle = [vertex(-1.0, -1.0), vertex(3.0, -1.0), vertex(-1.0, 3.0)];
    let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: bytemuck::cast_slice(&triangle),
        usage: wgpu::BufferUsages::VERTEX,
    });
    let target = texture(&device, format, wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC);
    let depth = texture(&device, depth_format, wgpu::TextureUsages::RENDER_ATTACHMENT);
    let (target_view, depth_view) = (target.create_view(&Default::default()), depth.create_view(&Default::default()));
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut render_pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &target_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations { load: wgpu::LoadOp::Clear(wgpu::Color::BLACK), store: wgpu::StoreOp::Store },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &depth_view,
                depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
                stencil_ops: None,
            }),
            ..Default::default()
        });
        {render_pass}
    }
    queue.submit([encoder.finish()]);
    let [r, g, b, a] = pixel(&device, &queue, &target)?;
    println!("pixel {r} {g} {b} {a}");
    no_hitches(&device)?;
    first_shader_pixels(&device, &queue)
}

/// Section 8: a trace recorded, then a warm-up from it.
#[allow(unused)]
fn no_hitches(device: &wgpu::Device) -> Result<(), Box<dyn std::error::Error>> {
    {no_hitches}
    Ok(())
}

/// Section 8: a new combination drawn while its pipeline is created (compiled, not run: the
/// example project's passes have no ubershader; tests/it/ubershader.rs runs the same calls).
#[allow(unused, dead_code)]
fn ubershader(
    device: &wgpu::Device,
    material: &kiln_runtime::manifest::MaterialManifest,
    targets: &kiln_runtime::Targets,
    mut render_pass: wgpu::RenderPass<'_>,
) -> Result<(), Box<dyn std::error::Error>> {
    let library = || kiln_runtime::Library::embedded(shaders::MANIFEST_JSON, shaders::MATERIALS_JSON, &shaders::PACKS);
    {ubershader}
    Ok(())
}

/// The pixel at (4, 4) of an 8 x 8 `Rgba8Unorm` target, read back.
fn pixel(device: &wgpu::Device, queue: &wgpu::Queue, target: &wgpu::Texture) -> Result<[u8; 4], Box<dyn std::error::Error>> {
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: 256 * 8,
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    encoder.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo { buffer: &readback, layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(256), rows_per_image: None } },
        target.size(),
    );
    queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |_| {});
    device.poll(wgpu::PollType::wait_indefinitely())?;
    let bytes = readback.get_mapped_range(..)?;
    Ok(bytes[4 * 256 + 4 * 4..4 * 256 + 4 * 4 + 4].try_into()?)
}

/// docs/first-shader.md's `draw_flat` for each material named on the command line, run in the
/// page's project folder (the first argument, built there); prints each one's pixel.
fn first_shader_pixels(device: &wgpu::Device, queue: &wgpu::Queue) -> Result<(), Box<dyn std::error::Error>> {
    let mut arguments = std::env::args().skip(1);
    let Some(project) = arguments.next() else { return Ok(()) };
    std::env::set_current_dir(project)?;
    for material in arguments {
        let target = texture(device, wgpu::TextureFormat::Rgba8Unorm, wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC);
        draw_flat(device, queue, &target.create_view(&Default::default()), &material)?;
        let pixel = pixel(device, queue, &target)?;
        println!("first-shader {material} {} {} {} {}", pixel[0], pixel[1], pixel[2], pixel[3]);
    }
    Ok(())
}

{first_shader}
"#;

#[test]
fn a_renderer_written_from_the_docs_builds_and_draws() {
    let test = "a_renderer_written_from_the_docs_builds_and_draws";
    if !crate::support::crate_tests(test) || crate::support::gpu(test).is_none() {
        return;
    }
    let page = std::fs::read_to_string(root().join("docs/renderer.md")).expect("docs/renderer.md");
    let rust = code_blocks(&page, "rust");
    let toml = code_blocks(&page, "toml");
    let [build_rs, generated_module, materials, per_frame, render_pass, no_hitches, ubershader] = &rust[..]
    else {
        panic!("docs/renderer.md's Rust blocks changed: {} of them", rust.len());
    };
    let dir = tempfile::tempdir().expect("tempdir");
    let krate = dir.path().join("my-renderer");
    // Dependencies as the page gives them, kiln's path pointing at this checkout; the harness
    // adds pollster to wait for the adapter.
    let dependencies = toml[0].replace("path = \"../kiln", &format!("path = \"{}", root().display()));
    let manifest = format!(
        "[package]\nname = \"my-renderer\"\nversion = \"0.1.0\"\nedition = \"2024\"\npublish = false\n\n{}\n\n\
         [dependencies.pollster]\nversion = \"0.4\"\n\n[workspace]\n",
        dependencies.trim_end()
    );
    write(&krate.join("Cargo.toml"), &manifest);
    let (readme_build_rs, readme_main) = readme_functions();
    write(&krate.join("build.rs"), &format!("{build_rs}{readme_build_rs}"));
    // The example project's shaders and materials, where the build script looks.
    for (from, to) in [("fixtures/project/shaders", "shaders"), ("fixtures/project/materials", "materials")] {
        for entry in std::fs::read_dir(root().join(from)).expect("fixtures") {
            let path = entry.expect("entry").path();
            std::fs::create_dir_all(krate.join(to)).expect("mkdir");
            std::fs::copy(&path, krate.join(to).join(path.file_name().expect("name"))).expect("copy");
        }
    }
    let (first_project, first_draw, pixels) = first_shader_project(dir.path());
    let mut main = HARNESS
        .replace("{first_shader}", &first_draw)
        .replace("{generated_module}", &format!("use wgpu::util::DeviceExt as _;\n{generated_module}"))
        .replace("{materials_to_bind_groups}", materials)
        .replace("{per_frame_and_per_object}", per_frame)
        .replace("{render_pass}", render_pass)
        .replace("{no_hitches}", no_hitches)
        .replace("{ubershader}", ubershader);
    main.push_str(&readme_main);
    write(&krate.join("src/main.rs"), &main);
    let mut arguments = vec!["run", "--quiet", "--", first_project.to_str().expect("UTF-8")];
    arguments.extend(pixels.iter().map(|(material, _)| material.as_str()));
    let run = cargo_scratch(&krate, &arguments);
    let (stdout, stderr) = (String::from_utf8_lossy(&run.stdout), String::from_utf8_lossy(&run.stderr));
    assert!(
        run.status.success(),
        "the crate from docs/renderer.md fails:\n{stdout}\n{stderr}\n--- src/main.rs\n{main}"
    );
    // LitClip's `_BaseColor` (0.3, 0.8, 0.2) lit head-on: green, far from the black clear colour.
    let pixel: Vec<u32> = stdout
        .lines()
        .find_map(|l| l.strip_prefix("pixel "))
        .expect("the pixel printed")
        .split(' ')
        .map(|v| v.parse().expect("a number"))
        .collect();
    assert!(pixel[1] > 60 && pixel[1] > pixel[0] && pixel[1] > pixel[2], "{pixel:?}\n{stdout}");
    // docs/first-shader.md's table, pixel by pixel (one step of 255 for rounding).
    for (material, expected) in &pixels {
        let drawn: Vec<i32> = stdout
            .lines()
            .find_map(|l| l.strip_prefix(&format!("first-shader {material} ")))
            .unwrap_or_else(|| panic!("no pixel for {material}:\n{stdout}"))
            .split(' ')
            .map(|v| v.parse().expect("a number"))
            .collect();
        assert!(
            drawn.iter().zip(expected).all(|(d, e)| (d - e).abs() <= 1),
            "docs/first-shader.md says {material} draws {expected:?}; it draws {drawn:?}"
        );
    }
}

/// docs/first-shader.md's files, written into `dir/first-shader` as the page gives them (each
/// block's first line, a comment, names its file); its `kiln list` text checked against a fresh
/// listing and the project built with `kiln build`. Returns the folder, the page's `draw_flat`,
/// and the pixel its table gives each material.
fn first_shader_project(dir: &Path) -> (std::path::PathBuf, String, Vec<(String, Vec<i32>)>) {
    let page = std::fs::read_to_string(root().join("docs/first-shader.md")).expect("docs/first-shader.md");
    let project = dir.join("first-shader");
    let files: Vec<String> =
        ["shader", "toml"].iter().flat_map(|language| code_blocks(&page, language)).collect();
    assert_eq!(files.len(), 4, "the shader, two materials and kiln.toml");
    for block in &files {
        let first = block.lines().next().unwrap_or_default();
        let name = first.trim_start_matches(['/', '#']).trim();
        write(&project.join(name), block);
    }
    let listing = code_blocks(&page, "text").into_iter().next().expect("the page's listing");
    let list = crate::support::kiln_in(&project, &["list"]);
    assert!(list.status.success(), "{}", String::from_utf8_lossy(&list.stderr));
    assert_eq!(String::from_utf8_lossy(&list.stdout), listing, "docs/first-shader.md's listing is stale");
    let build = crate::support::kiln_in(&project, &["build"]);
    let stderr = String::from_utf8_lossy(&build.stderr);
    assert!(build.status.success() && stderr.starts_with("built 1 shader,"), "{stderr}");
    let draw = code_blocks(&page, "rust").into_iter().next().expect("the page's draw_flat");
    let pixels = page
        .lines()
        .filter_map(|row| {
            let cells: Vec<&str> = row.split('|').map(str::trim).collect();
            let numbers: Vec<i32> =
                cells.get(3)?.split(", ").map(|v| v.parse().ok()).collect::<Option<_>>()?;
            (numbers.len() == 4).then(|| (cells[1].to_string(), numbers))
        })
        .collect::<Vec<_>>();
    assert_eq!(pixels.len(), 2, "a pixel for each material");
    (project, draw, pixels)
}

/// The README's Rust blocks, compiled (not run) in the same crate, each in a function of its
/// own: its build script's `fn main` for the crate's build.rs, and the generated module's use
/// and the run time's for its main.rs, with what the README assumes (`device`, `format`,
/// `depth_format`) as parameters.
fn readme_functions() -> (String, String) {
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let blocks = code_blocks(&readme, "rust");
    let [build_script, generated_module, runtime] = &blocks[..] else {
        panic!("the README's Rust blocks changed: {} of them", blocks.len());
    };
    // The build script's block goes where the compiler is a dependency: the crate's build.rs.
    let for_build_rs =
        format!("\n#[allow(dead_code, unused)]\nfn readme_build_script() {{\n{build_script}}}\n");
    let for_main = format!(
        "\n#[allow(dead_code, unused)]\nfn readme_generated_module() -> Result<(), Box<dyn std::error::Error>> {{\n{generated_module}    Ok(())\n}}\n\n\
         #[allow(dead_code, unused)]\nfn readme_runtime(device: wgpu::Device, format: wgpu::TextureFormat, depth_format: wgpu::TextureFormat) -> Result<(), Box<dyn std::error::Error>> {{\n{runtime}    Ok(())\n}}\n"
    );
    (for_build_rs, for_main)
}

fn write(path: &Path, text: &str) {
    std::fs::create_dir_all(path.parent().expect("folder")).expect("mkdir");
    std::fs::write(path, text).expect("write");
}

/// The README's example outputs are what kiln prints today: its `kiln list` block is part of a
/// fresh listing of the bundled project, word for word, and its build line is a fresh build's
/// (bytes and time aside, which move with every change).
#[test]
fn the_readme_s_example_outputs_are_what_kiln_prints() {
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    // Every fenced block's text, whatever its language (a `sh` block's closing fence opens none).
    let mut blocks: Vec<String> = Vec::new();
    let mut open: Option<String> = None;
    for line in readme.lines() {
        match (open.as_mut(), line.starts_with("```")) {
            (None, true) => open = Some(String::new()),
            (Some(_), true) => blocks.extend(open.take()),
            (Some(block), false) => {
                block.push_str(line);
                block.push('\n');
            }
            (None, false) => {}
        }
    }
    let listing = blocks.iter().find(|b| b.starts_with("Custom RP/Lit (")).expect("the list example");
    let list = crate::support::kiln(&["list", "fixtures/project"]);
    assert!(list.status.success());
    let fresh = String::from_utf8_lossy(&list.stdout);
    assert!(fresh.contains(listing.as_str()), "README:\n{listing}\nkiln list:\n{fresh}");

    let line = blocks.iter().find(|b| b.starts_with("built ")).expect("the build example").trim().to_string();
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    let build =
        crate::support::kiln(&["build", "fixtures/project", "--output", output.to_str().expect("UTF-8")]);
    assert!(build.status.success(), "{}", String::from_utf8_lossy(&build.stderr));
    // The summary goes to stderr, with the diagnostics.
    let stderr = String::from_utf8_lossy(&build.stderr);
    let fresh = stderr.lines().find(|l| l.starts_with("built ")).expect("a summary line");
    // Up to the bytes written: the counts of shaders, passes, variants and modules.
    let counts = |l: &str| l.split("), ").next().map(str::to_string);
    assert_eq!(counts(&line), counts(fresh), "README: {line}\nkiln build: {fresh}");
}

/// docs/first-shader.md's project lists and builds as the page says, with or without a GPU (the
/// draw is checked in `a_renderer_written_from_the_docs_builds_and_draws`).
#[test]
fn the_first_shader_page_lists_and_builds_as_it_says() {
    let dir = tempfile::tempdir().expect("tempdir");
    let (_, draw, pixels) = first_shader_project(dir.path());
    assert!(draw.contains("fn draw_flat("), "{draw}");
    assert_eq!(pixels.iter().map(|(m, _)| m.as_str()).collect::<Vec<_>>(), ["Dim", "Inverted"]);
}
