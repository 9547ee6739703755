//! Where `raybook render` writes its picture: in the format that the name's
//! extension says, and only into a regular file.
//!
//! A picture is written whole or not at all: to a new file beside the
//! target, then renamed over it (the toolkit's `write_atomically`), so a
//! reader never sees half a picture. Renaming replaces the name itself:
//! over a device such as /dev/null it would put a file where the device
//! was, over a named pipe it would remove the pipe, and over a directory
//! it fails. So a target that exists must be a regular file, or a symbolic
//! link to one (the picture then replaces the file it points to, and the
//! link stays). `-o /dev/null`, to time a render without keeping it, is
//! refused with the rest: the time is printed either way, and `raybook
//! bench` times renders properly.

use std::io::Cursor;
use std::path::{Path, PathBuf};

use image::codecs::pnm::{PnmEncoder, PnmSubtype, SampleEncoding};
use image::{ImageFormat, RgbImage};
use raybook::toolkit::Image;
use raybook::toolkit::image::write_atomically;

/// A format that `-o` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Png,
    /// Binary PPM (P6), the colour format of the Netpbm family.
    Ppm,
    Bmp,
    Tga,
}

/// The extensions `-o` knows (in any case), and their formats.
pub const EXTENSIONS: [(&str, Format); 5] = [
    ("png", Format::Png),
    ("ppm", Format::Ppm),
    ("pnm", Format::Ppm),
    ("bmp", Format::Bmp),
    ("tga", Format::Tga),
];

impl Format {
    /// The format that the extension of `path` names, or why it names none
    /// that `-o` writes.
    pub fn of(path: &Path) -> Result<Format, String> {
        let known = "end it in .png, .ppm (or .pnm), .bmp or .tga";
        let Some(extension) = path.extension() else {
            return Err(format!(
                "{}: the name has no extension to say the picture's format; {known}",
                path.display()
            ));
        };
        let extension = extension.to_string_lossy();
        let found = EXTENSIONS
            .iter()
            .find(|(e, _)| e.eq_ignore_ascii_case(&extension));
        found.map(|&(_, format)| format).ok_or_else(|| {
            format!(
                "{}: raybook cannot write .{extension} pictures; {known}",
                path.display()
            )
        })
    }

    /// The picture in this format.
    pub fn encode(self, image: &Image) -> Vec<u8> {
        if self == Format::Png {
            return image.to_png();
        }
        let rgb = image.to_rgb8();
        let mut bytes = Vec::new();
        let written = match self {
            Format::Ppm => ppm(&rgb, &mut bytes),
            Format::Bmp => rgb.write_to(&mut Cursor::new(&mut bytes), ImageFormat::Bmp),
            _ => rgb.write_to(&mut Cursor::new(&mut bytes), ImageFormat::Tga),
        };
        written.expect("encoding an 8-bit RGB picture in memory cannot fail");
        bytes
    }
}

/// Binary PPM (P6), whatever the encoder would choose by itself.
fn ppm(rgb: &RgbImage, bytes: &mut Vec<u8>) -> image::ImageResult<()> {
    let subtype = PnmSubtype::Pixmap(SampleEncoding::Binary);
    rgb.write_with_encoder(PnmEncoder::new(bytes).with_subtype(subtype))
}

/// Where a picture goes: checked before the render, so that a name that
/// cannot be written costs no rendering, and again just before writing.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Output {
    /// As the user named it.
    pub path: PathBuf,
    pub format: Format,
}

impl Output {
    /// The output at `path`, or why a picture cannot go there (`-o PATH:
    /// what is wrong`).
    pub fn new(path: &Path) -> Result<Output, String> {
        let format = writable(path)
            .and_then(|_| Format::of(path))
            .map_err(|e| format!("-o {e}"))?;
        Ok(Output {
            path: path.to_owned(),
            format,
        })
    }

    /// Writes the picture, whole or not at all (see the module's text).
    pub fn write(&self, image: &Image) -> Result<(), String> {
        let file = writable(&self.path)?;
        let bytes = self.format.encode(image);
        let written = write_atomically(&file, &bytes);
        written.map_err(|e| format!("cannot write {}: {e}", self.path.display()))
    }
}

/// The file to write the picture into at `path`: `path` itself when
/// nothing is there yet or a regular file is, the file it points to when it
/// is a symbolic link to a regular file; refused otherwise.
fn writable(path: &Path) -> Result<PathBuf, String> {
    let refuse = |why: String| format!("{}: {why}", path.display());
    let link = match std::fs::symlink_metadata(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(path.to_owned()),
        Err(e) => return Err(refuse(e.to_string())),
        Ok(found) => found.file_type().is_symlink(),
    };
    let target = std::fs::metadata(path).map_err(|e| {
        refuse(format!(
            "cannot follow the symbolic link to where the picture would go: {e}"
        ))
    })?;
    if !target.is_file() {
        return Err(refuse(format!(
            "it is {}, not a regular file; raybook writes a picture only into a regular \
             file, which it replaces whole (a new file renamed into place)",
            kind_of(&target.file_type())
        )));
    }
    match link {
        true => std::fs::canonicalize(path).map_err(|e| refuse(e.to_string())),
        false => Ok(path.to_owned()),
    }
}

/// What a file that is not a regular file is, for messages.
fn kind_of(kind: &std::fs::FileType) -> &'static str {
    if kind.is_dir() {
        return "a directory (name a file in it, such as DIR/render.png)";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "a named pipe (FIFO)";
        }
        if kind.is_char_device() || kind.is_block_device() {
            return "a device";
        }
        if kind.is_socket() {
            return "a socket";
        }
    }
    "not a file"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_extension_names_the_format_in_any_case() {
        let of = |name: &str| Format::of(Path::new(name));
        assert_eq!(of("a/out.png"), Ok(Format::Png));
        assert_eq!(of("out.PPM"), Ok(Format::Ppm));
        assert_eq!(of("out.pnm"), Ok(Format::Ppm));
        assert_eq!(of("out.Bmp"), Ok(Format::Bmp));
        assert_eq!(of("out.tga"), Ok(Format::Tga));
        let e = of("out.jpg").unwrap_err();
        assert!(
            e.starts_with("out.jpg: raybook cannot write .jpg pictures;"),
            "{e}"
        );
        assert!(of("out").unwrap_err().contains("no extension"));
    }

    #[test]
    fn each_format_starts_as_its_kind_of_file_does() {
        let image = Image {
            width: 3,
            height: 2,
            pixels: vec![raybook::toolkit::Color::new(1.0, 0.5, 0.0); 6],
        };
        let magic: [(Format, &[u8]); 3] = [
            (Format::Png, b"\x89PNG"),
            (Format::Ppm, b"P6\n3 2 255\n"),
            (Format::Bmp, b"BM"),
        ];
        for (format, start) in magic {
            assert!(format.encode(&image).starts_with(start), "{format:?}");
        }
        let tga = Format::Tga.encode(&image);
        assert_eq!(
            (tga[12], tga[14]),
            (3, 2),
            "a TGA header's width and height"
        );
    }

    #[test]
    fn every_format_holds_the_same_pixels() {
        let pixels = (0..12).map(|i| raybook::toolkit::Color::splat(i as f32 / 11.0));
        let image = Image {
            width: 4,
            height: 3,
            pixels: pixels.collect(),
        };
        let formats = [
            (Format::Ppm, ImageFormat::Pnm),
            (Format::Bmp, ImageFormat::Bmp),
            (Format::Tga, ImageFormat::Tga),
        ];
        for (format, decoder) in formats {
            let bytes = format.encode(&image);
            let decoded = image::load_from_memory_with_format(&bytes, decoder).unwrap();
            assert_eq!(decoded.to_rgb8(), image.to_rgb8(), "{format:?}");
        }
    }

    #[test]
    fn only_regular_files_are_written_over() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("old.png");
        std::fs::write(&file, "old").unwrap();
        assert!(Output::new(&file).is_ok());
        assert!(Output::new(&dir.path().join("new.png")).is_ok());
        std::fs::create_dir(dir.path().join("sub.png")).unwrap();
        let e = Output::new(&dir.path().join("sub.png")).unwrap_err();
        assert!(
            e.starts_with("-o ") && e.contains("it is a directory"),
            "{e}"
        );
    }

    #[cfg(unix)]
    #[test]
    fn a_link_to_a_picture_keeps_its_link_and_a_link_to_a_device_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let (file, link) = (dir.path().join("a.png"), dir.path().join("link.png"));
        std::fs::write(&file, "old").unwrap();
        std::os::unix::fs::symlink(&file, &link).unwrap();
        let image = Image {
            width: 1,
            height: 1,
            pixels: vec![raybook::toolkit::Color::ONE],
        };
        Output::new(&link).unwrap().write(&image).unwrap();
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert!(std::fs::read(&file).unwrap().starts_with(b"\x89PNG"));
        let device = dir.path().join("null.png");
        std::os::unix::fs::symlink("/dev/null", &device).unwrap();
        let e = Output::new(&device).unwrap_err();
        assert!(e.contains("it is a device"), "{e}");
        let e = writable(Path::new("/dev/null")).unwrap_err();
        assert!(e.starts_with("/dev/null: it is a device"), "{e}");
    }
}
