#pragma once
/// Where exported frames go. The PNG sequence is the one sink today; video
/// export will be another FrameSink (fed by the CLI's encoder in f2::io when
/// it lands) and plugs into AnimationExporter without other changes: add the
/// sink, then enable MainWindow's "Export Video…" action (see docs/viewer.md).
#include <QString>
#include <string>

#include "core/render/image.h"

namespace f2::viewer {

class FrameSink {
   public:
    virtual ~FrameSink() = default;
    /// Called once before the first frame. False (and `error`) aborts the export.
    virtual bool begin(int width, int height, int fps, int frameCount, std::string& error) = 0;
    /// Called for frames in order; `index` counts from 0.
    virtual bool write(const Image& image, int index, std::string& error) = 0;
    /// Called once after the last frame, or after a cancel (`cancelled`).
    virtual bool finish(bool cancelled, std::string& error) = 0;
    /// Human-readable destination, for messages.
    virtual QString destination() const = 0;
};

/// `<dir>/<stem>_0000.png`, `<stem>_0001.png`, ... written atomically by f2::io.
class PngSequenceSink : public FrameSink {
   public:
    PngSequenceSink(QString directory, QString stem);
    bool begin(int width, int height, int fps, int frameCount, std::string& error) override;
    bool write(const Image& image, int index, std::string& error) override;
    bool finish(bool cancelled, std::string& error) override;
    QString destination() const override;
    /// File name of frame `index` (after begin()).
    QString fileName(int index) const;

   private:
    QString directory_;
    QString stem_;
    int digits_ = 4;
};

}  // namespace f2::viewer
