// image_io.cpp - the OpenImageIO adapter behind image_io.h.
#include "image_io.h"
#include "log.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

using namespace OIIO;

static bool fail(char* err, size_t err_size, const char* file, const std::string& problem)
{
    std::string one_line = problem;
    for (char& c : one_line)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!one_line.empty() && one_line.back() == ' ')
        one_line.pop_back();
    std::snprintf(err, err_size, "%s: %s", file, one_line.c_str());
    return false;
}

// glTF colour and alpha are independent (unassociated). OIIO premultiplies
// on read and un-premultiplies on write unless told otherwise, which would
// change RGB wherever alpha < 1.
static const ImageSpec& unassociated_config()
{
    static const ImageSpec config = [] {
        ImageSpec s;
        s.attribute("oiio:UnassociatedAlpha", 1);
        return s;
    }();
    return config;
}

// OIIO 2.4's PNG reader leaves libpng's default handlers in place, which
// print "libpng error: ..." on stderr before OIIO returns the same text as
// its error. While decoding, fd 2 goes to a temporary file; what was caught
// is dropped on failure (the error carries it) and logged as debug output on
// success (libpng warnings). Scene loading decodes images before any other
// thread writes to stderr.
class StderrCapture {
public:
    StderrCapture()
    {
        std::fflush(stderr);
        file_ = std::tmpfile();
        saved_ = file_ ? dup(2) : -1;
        if (saved_ >= 0)
            dup2(fileno(file_), 2);
    }
    ~StderrCapture() { finish(); }
    std::string finish()
    {
        std::string text;
        if (saved_ >= 0) {
            std::fflush(stderr);
            dup2(saved_, 2);
            close(saved_);
            saved_ = -1;
            std::rewind(file_);
            char buf[512];
            for (size_t n; (n = std::fread(buf, 1, sizeof buf, file_)) > 0;)
                text.append(buf, n);
        }
        if (file_)
            std::fclose(file_);
        file_ = nullptr;
        return text;
    }

private:
    FILE* file_ = nullptr;
    int saved_ = -1;
};

// Decodes an opened input into a malloc'd RGBA8 buffer.
static bool decode_rgba8(ImageInput* in, const char* file, uint8_t** rgba8, uint32_t* width,
                         uint32_t* height, char* err, size_t err_size)
{
    const ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
        return fail(err, err_size, file, "unsupported image dimensions");
    size_t w = (size_t)spec.width, h = (size_t)spec.height, nc = (size_t)spec.nchannels;
    if (w > SCN_IMAGE_MAX_SIDE || h > SCN_IMAGE_MAX_SIDE || w * h > SCN_IMAGE_MAX_PIXELS || nc > 64)
        return fail(err, err_size, file,
                    "image claims " + std::to_string(w) + "x" + std::to_string(h) + " pixels, " +
                        std::to_string(nc) + " channels; the limit is " + std::to_string(SCN_IMAGE_MAX_SIDE) +
                        " per side and " + std::to_string(SCN_IMAGE_MAX_PIXELS) + " pixels (64 channels)");
    std::vector<uint8_t> src(w * h * nc);
    if (!in->read_image(0, 0, 0, (int)nc, TypeDesc::UINT8, src.data()))
        return fail(err, err_size, file, "cannot decode image: " + in->geterror());
    uint8_t* out = (uint8_t*)std::malloc(w * h * 4);
    if (!out)
        return fail(err, err_size, file, "out of memory for the decoded image");
    for (size_t p = 0; p < w * h; p++) {
        const uint8_t* s = &src[p * nc];
        uint8_t* d = out + 4 * p;
        bool grey = nc < 3;
        d[0] = s[0];
        d[1] = grey ? s[0] : s[1];
        d[2] = grey ? s[0] : s[2];
        d[3] = nc == 2 ? s[1] : nc >= 4 ? s[3] : 255;
    }
    *rgba8 = out;
    *width = (uint32_t)w;
    *height = (uint32_t)h;
    return true;
}

static bool decoded(bool ok, StderrCapture& capture, const char* file)
{
    std::string caught = capture.finish();
    for (char& c : caught)
        if (c == '\n' || c == '\r')
            c = ' ';
    if (ok && !caught.empty())
        tv_log(TV_LOG_DEBUG, "%s: decoder said: %s", file, caught.c_str());
    return ok;
}

bool scn_image_read(const char* path, uint8_t** rgba8, uint32_t* width, uint32_t* height, char* err,
                    size_t err_size)
{
    *rgba8 = nullptr;
    if (!Filesystem::is_regular(path))
        return fail(err, err_size, path, "image file not found");
    StderrCapture capture;
    auto in = ImageInput::open(path, &unassociated_config());
    if (!in)
        return fail(err, err_size, path, "cannot open image: " + OIIO::geterror());
    return decoded(decode_rgba8(in.get(), path, rgba8, width, height, err, err_size), capture, path);
}

bool scn_image_read_memory(const void* data, size_t size, const char* name, uint8_t** rgba8,
                           uint32_t* width, uint32_t* height, char* err, size_t err_size)
{
    *rgba8 = nullptr;
    const unsigned char* b = (const unsigned char*)data;
    // OIIO picks the reader by the name's extension; sniff the common
    // magic numbers so embedded images need no file name.
    std::string probe = name;
    if (size >= 8 && std::memcmp(b, "\x89PNG", 4) == 0)
        probe = "embedded.png";
    else if (size >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF)
        probe = "embedded.jpg";
    Filesystem::IOMemReader reader(data, size);
    // With a config, OIIO 2.4 readers take the proxy from the config's
    // "oiio:ioproxy" attribute only (the open() argument is then ignored).
    ImageSpec config = unassociated_config();
    void* proxy = &reader;
    config.attribute("oiio:ioproxy", TypeDesc::PTR, &proxy);
    StderrCapture capture;
    auto in = ImageInput::open(probe, &config, &reader);
    if (!in)
        return fail(err, err_size, name, "cannot decode embedded image: " + OIIO::geterror());
    return decoded(decode_rgba8(in.get(), name, rgba8, width, height, err, err_size), capture, name);
}

void scn_image_free(uint8_t* rgba8)
{
    std::free(rgba8);
}

static bool write_image(const char* path, const void* pixels, uint32_t width, uint32_t height,
                        uint32_t channels, TypeDesc type, char* err, size_t err_size)
{
    auto out = ImageOutput::create(path);
    if (!out)
        return fail(err, err_size, path, "no image writer for this file name: " + OIIO::geterror());
    ImageSpec spec((int)width, (int)height, (int)channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->open(path, spec))
        return fail(err, err_size, path, "cannot create image file: " + out->geterror());
    if (!out->write_image(type, pixels)) {
        std::string problem = out->geterror();
        out->close();
        std::remove(path); // no partial output
        return fail(err, err_size, path, "cannot write image: " + problem);
    }
    if (!out->close())
        return fail(err, err_size, path, "cannot finish image file: " + out->geterror());
    return true;
}

bool scn_image_write_png(const char* path, const uint8_t* pixels, uint32_t width, uint32_t height,
                         uint32_t channels, char* err, size_t err_size)
{
    if (channels != 3 && channels != 4)
        return fail(err, err_size, path, "PNG output needs 3 or 4 channels");
    return write_image(path, pixels, width, height, channels, TypeDesc::UINT8, err, err_size);
}

bool scn_image_write_exr(const char* path, const float* pixels, uint32_t width, uint32_t height,
                         uint32_t channels, char* err, size_t err_size)
{
    if (channels < 1 || channels > 4)
        return fail(err, err_size, path, "EXR output needs 1 to 4 channels");
    return write_image(path, pixels, width, height, channels, TypeDesc::FLOAT, err, err_size);
}

bool scn_image_psnr_oiio(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height,
                         double* psnr, char* err, size_t err_size)
{
    ImageSpec spec((int)width, (int)height, 3, TypeDesc::UINT8);
    // ImageBuf wraps caller memory without copying; compare only reads it.
    ImageBuf ia(spec, const_cast<uint8_t*>(a));
    ImageBuf ib(spec, const_cast<uint8_t*>(b));
    // Thresholds above any possible difference: compare() flags `error` when
    // a pixel exceeds failthresh, and we only want the statistics.
    ImageBufAlgo::CompareResults r = ImageBufAlgo::compare(ia, ib, 2.0f, 2.0f);
    if (r.error)
        return fail(err, err_size, "psnr", "ImageBufAlgo::compare failed: " + OIIO::geterror());
    *psnr = r.rms_error == 0.0 ? std::numeric_limits<double>::infinity() : r.PSNR;
    return true;
}
