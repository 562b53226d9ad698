#pragma once

namespace footpath {

class AnalysisSession;

/// A view of the analysis session. The window keeps a list of its views and hands each change of
/// the session to all of them alike, so a new view is its own files plus one entry in that list
/// (MainWindow::sessionViews): it reads what it draws from the session (the result, its
/// evaluation, the parameters the result was estimated with, the recording).
class SessionView {
public:
    virtual ~SessionView() = default;
    /// The session has a new recording (its estimate follows with showEstimate).
    virtual void showRecording(const AnalysisSession& /*session*/) {}
    /// The session has a new estimate, or none (session.result() null: show nothing of the last).
    virtual void showEstimate(const AnalysisSession& session) = 0;
    /// The time cursor moved (a click in any view, a step chosen in the table).
    virtual void showTimeCursor(double /*time_s*/) {}
};

}  // namespace footpath
