//! A scene that meets a new keyword combination every frame (`fixtures/ubershader`'s pass, one
//! cell of a grid per combination), drawn two ways: asking `Runtime::pipeline`, which creates a
//! new combination's pipeline on the render thread, or `Runtime::drawable`, which draws it with
//! the pass's ubershader while a worker creates the pipeline (docs/keywords.md).

use crate::Image;
use kiln_runtime::manifest::MaterialManifest;
use kiln_runtime::{Drawable, Library, PipelineRequest, Runtime, Targets};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// What kiln generated for `fixtures/ubershader`.
pub mod shaders {
    include!(concat!(env!("OUT_DIR"), "/ubershader/kiln_shaders.rs"));
}

const SHADER: &str = "Test/Ubershader";
/// Cells of the grid, one per keyword combination, and each cell's size in pixels.
const COLUMNS: u32 = 6;
const ROWS: u32 = 4;
const CELL: u32 = 16;

/// The build of `fixtures/ubershader` the program embeds.
pub fn library() -> Result<Library, String> {
    Library::embedded(shaders::MANIFEST_JSON, shaders::MATERIALS_JSON, &shaders::PACKS)
        .map_err(|e| e.to_string())
}

/// Every keyword combination of the pass (24), in the order the scene meets them.
pub fn combinations() -> Vec<Vec<&'static str>> {
    let mut all = Vec::new();
    for tint in [None, Some("_TINT_RED"), Some("_TINT_GREEN")] {
        for fog in [None, Some("_FOG")] {
            for far in [None, Some("_FAR")] {
                for dim in [None, Some("_DIM")] {
                    all.push([tint, fog, far, dim].into_iter().flatten().collect());
                }
            }
        }
    }
    all
}

/// One frame: how long the render thread spent in it (asking, encoding, submitting and waiting
/// for the GPU) and how many cells the ubershader drew.
#[derive(Debug, Clone, Copy)]
pub struct Frame {
    /// The frame's time on the render thread.
    pub time: Duration,
    /// Cells drawn by the ubershader while their pipeline was being made.
    pub fallbacks: usize,
}

/// What [`introduce`] measured.
pub struct Introduced {
    /// Each frame, one more combination than the last.
    pub frames: Vec<Frame>,
    /// Creating the ubershader's pipeline before the first frame (with `fallback`).
    pub warm_up: Option<Duration>,
    /// Each variant's pipeline creation: on which thread and how long.
    pub created: Vec<kiln_runtime::Creation>,
    /// The grid with every combination, drawn once all pipelines are ready.
    pub image: Image,
}

/// Draws frame after frame, one more combination each, with `Runtime::drawable` (`fallback`) or
/// `Runtime::pipeline`; then waits for the workers and draws the whole grid once more.
pub fn introduce(device: &wgpu::Device, queue: &wgpu::Queue, fallback: bool) -> Result<Introduced, String> {
    let runtime = Arc::new(Runtime::new(device, library()?));
    if fallback && !runtime.draws_ubershaders() {
        return Err("the device has no immediate data (wgpu's IMMEDIATES): no ubershader".into());
    }
    let material = MaterialManifest {
        name: "Plain".into(),
        shader: SHADER.into(),
        preset: None,
        render_queue: 2000,
        keywords: Vec::new(),
        values: Default::default(),
    };
    let targets = Targets {
        colors: vec![wgpu::TextureFormat::Rgba8Unorm],
        depth: Some(wgpu::TextureFormat::Depth32Float),
        samples: 1,
    };
    let ask = |keywords: &[&str]| -> Result<Drawable, String> {
        let request = PipelineRequest {
            variant: runtime.variant(SHADER, 0, keywords).map_err(|e| e.to_string())?,
            material: &material,
            targets: &targets,
            vertex_layout: None,
            overrides: &[],
        };
        let drawable = if fallback {
            runtime.drawable(&request)
        } else {
            runtime.pipeline(&request).map(Drawable::Ready)
        };
        drawable.map_err(|e| e.to_string())
    };
    let warm_up = if fallback {
        let started = Instant::now();
        let request = PipelineRequest {
            variant: runtime.variant(SHADER, 0, &[]).map_err(|e| e.to_string())?,
            material: &material,
            targets: &targets,
            vertex_layout: None,
            overrides: &[],
        };
        runtime.warm_up_ubershader(&request).map_err(|e| e.to_string())?;
        Some(started.elapsed())
    } else {
        None
    };
    runtime.mark_warm();
    // A game has drawn frames before it meets a new combination: the first submission's costs
    // are not the pipelines'.
    draw_grid(device, queue, &[])?;
    let combinations = combinations();
    let mut frames = Vec::new();
    for count in 1..=combinations.len() {
        let started = Instant::now();
        let draws = combinations[..count].iter().map(|k| ask(k)).collect::<Result<Vec<_>, _>>()?;
        draw_grid(device, queue, &draws)?;
        let fallbacks = draws.iter().filter(|d| !d.is_ready()).count();
        frames.push(Frame { time: started.elapsed(), fallbacks });
    }
    let started = Instant::now();
    while runtime.pipelines_pending() > 0 {
        if started.elapsed() > Duration::from_secs(300) {
            return Err("the workers did not finish in 5 minutes".into());
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    let draws = combinations.iter().map(|k| ask(k)).collect::<Result<Vec<_>, _>>()?;
    if !draws.iter().all(Drawable::is_ready) {
        return Err("a pipeline is still not ready after the workers finished".into());
    }
    let image = draw_grid(device, queue, &draws)?;
    Ok(Introduced { frames, warm_up, created: runtime.created_after_warm_up(), image })
}

/// Draws cell i of the grid with draw i (a full-screen triangle in the cell's viewport), waits
/// for the GPU and reads the grid back.
pub fn draw_grid(device: &wgpu::Device, queue: &wgpu::Queue, draws: &[Drawable]) -> Result<Image, String> {
    use wgpu::util::DeviceExt;
    let (width, height) = (COLUMNS * CELL, ROWS * CELL);
    let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
    let texture = |format, usage| {
        device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | usage,
            view_formats: &[],
        })
    };
    let color = texture(wgpu::TextureFormat::Rgba8Unorm, wgpu::TextureUsages::COPY_SRC);
    let depth = texture(wgpu::TextureFormat::Depth32Float, wgpu::TextureUsages::empty());
    let vertices: [f32; 6] = [-1.0, -1.0, 3.0, -1.0, -1.0, 3.0];
    let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: bytemuck::cast_slice(&vertices),
        usage: wgpu::BufferUsages::VERTEX,
    });
    let row = (width * 4).div_ceil(256) * 256;
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(row * height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let (color_view, depth_view) =
            (color.create_view(&Default::default()), depth.create_view(&Default::default()));
        let mut pass = crate::begin_cleared(&mut encoder, &color_view, &depth_view, wgpu::Color::BLACK, None);
        pass.set_vertex_buffer(0, vertex_buffer.slice(..));
        for (i, draw) in draws.iter().enumerate() {
            let (x, y) = ((i as u32 % COLUMNS) * CELL, (i as u32 / COLUMNS) * CELL);
            pass.set_viewport(x as f32, y as f32, CELL as f32, CELL as f32, 0.0, 1.0);
            draw.set_on(&mut pass);
            pass.draw(0..3, 0..1);
        }
    }
    encoder.copy_texture_to_buffer(
        color.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: None },
        },
        size,
    );
    queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |_| {});
    device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| e.to_string())?;
    Image::read(&readback, width, height, row)
}
