// Frames as capture tools see them: a frame terminator where no swap ends a frame (headless), and
// RenderDoc's in-application API, found at run time in a process RenderDoc started (no build
// dependency), to capture chosen frames. docs/captures.md says how to use both.
#pragma once
#include <string>
#include <vector>

namespace oasis::gl {

// Headless commands turn frame terminators on (a window's swap already ends its frames; a
// terminator there too would split each frame in two).
void setFrameTerminators(bool on);

// Renderer::renderFrame calls beginFrame: it ends the frame still open (the view drawn and read
// after the last renderFrame belong to it) and starts an armed capture. endFrame ends the open
// frame; commands call it after their set-up (plant atlas: its own frame) and at their end.
// A frame ends with glFrameTerminatorGREMEDY where the context lists GL_GREMEDY_frame_terminator:
// apitrace's tracer and RenderDoc add it (both count frames by it), no driver has it.
void beginFrame();
void endFrame();

// RenderDoc's in-application API, when this process runs under RenderDoc (renderdoccmd capture, or
// the UI's launch): librenderdoc.so already loaded. Otherwise `why` says so.
bool renderDocLoaded(std::string* why = nullptr);
// Captures the next `frames` frames (each beginFrame to the next boundary is one capture file).
// Needs renderDocLoaded().
void armCaptures(int frames);
// Window: captures the next presented frame (RenderDoc's trigger, at the next swap).
void triggerWindowCapture();
// Capture files RenderDoc has written in this process, oldest first.
std::vector<std::string> renderDocCaptures();

}  // namespace oasis::gl
