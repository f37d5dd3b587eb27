// STEP and IGES through OpenCASCADE's data exchange (TKSTEP, TKIGES). Both writers convert
// Geom_BSplineCurve/Surface to the file's B-spline entities without approximation
// (GeomToStep_MakeBSplineCurveWithKnots..., GeomToIGES_GeomCurve); a periodic curve is written
// unwrapped (neither format has OCCT's periodic form), the same geometry.
#include "solvers/exchange/cad_writer.h"

#include "solvers/exchange/occt_geometry.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESData_IGESWriter.hxx>
#include <IGESSelect_WorkLibrary.hxx>
#include <Interface_FloatWriter.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Precision.hxx>
#include <STEPControl_Controller.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <StepData_StepWriter.hxx>
#include <XSControl_WorkSession.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <mutex>
#include <sstream>

namespace sculptline::solvers::exchange {
namespace {

// OCCT's default messenger prints the translators' progress on stdout, where sculptline-cli writes
// its JSON: it is silenced once per process (the writers report failures through their status).
void quietOcct()
{
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
        STEPControl_Controller::Init();
        IGESControl_Controller::Init();
    });
}

std::string indexed(const char* name, size_t i) { return std::string(name) + "[" + std::to_string(i) + "]"; }

// Reals with 17 significant digits, enough to read back the same double (IEEE 754 §5.12.2): the
// translators' own defaults keep 12 (STEP) and 9 (IGES) digits, up to 2e-9 relative, which moves
// a rational point of a 25 mm sphere by a nanometre. "%E" keeps the decimal point both formats need.
// Zero suppression stays off: in OCCT 7.6 it cuts the exponent of 17-digit mantissas (0.6 came
// back as 5.9999999999999).
void fullPrecision(Interface_FloatWriter& writer)
{
    writer.SetFormat("%.16E");  // resets the "%f" range form and zero suppression
    writer.SetZeroSuppress(Standard_False);
}

// STEPControl_Writer::Write takes a file name only (OCCT 7.6); its model is sent through
// StepData_StepWriter as StepSelect_WorkLibrary::WriteFile does, with full precision, to a stream.
std::string stepText(STEPControl_Writer& writer)
{
    const Handle(StepData_Protocol) protocol = Handle(StepData_Protocol)::DownCast(writer.WS()->Protocol());
    if (protocol.IsNull()) throw ExchangeError("format: the STEP translator has no protocol");
    StepData_StepWriter out(writer.Model());
    fullPrecision(out.FloatWriter());
    out.SendModel(protocol);
    std::ostringstream text;
    if (!out.Print(text)) throw ExchangeError("path: the STEP writer failed");
    return text.str();
}

}  // namespace

std::string encodeStep(const ExchangeContent& content)
{
    quietOcct();
    try {
        STEPControl_Writer writer;
        Interface_Static::SetCVal("write.step.schema", "AP214IS");
        Interface_Static::SetCVal("write.step.unit", "MM");
        BRep_Builder builder;
        TopoDS_Compound compound;
        builder.MakeCompound(compound);
        for (size_t i = 0; i < content.curves.size(); ++i) {
            const std::string field = indexed("curves", i);
            BRepBuilderAPI_MakeEdge edge(toOcct(content.curves[i], field));
            if (!edge.IsDone()) throw ExchangeError(field + ": OpenCASCADE cannot make an edge of it");
            builder.Add(compound, edge.Edge());
        }
        for (size_t i = 0; i < content.surfaces.size(); ++i) {
            const std::string field = indexed("surfaces", i);
            BRepBuilderAPI_MakeFace face(toOcct(content.surfaces[i], field), Precision::Confusion());
            if (!face.IsDone()) throw ExchangeError(field + ": OpenCASCADE cannot make a face of it");
            builder.Add(compound, face.Face());
        }
        if (writer.Transfer(compound, STEPControl_AsIs) != IFSelect_RetDone) {
            throw ExchangeError("curves: the STEP translator refused the geometry");
        }
        return stepText(writer);
    } catch (const Standard_Failure& e) {
        throw ExchangeError(std::string("curves: OpenCASCADE failed (") + e.GetMessageString() + ")");
    }
}

std::string encodeIges(const ExchangeContent& content)
{
    quietOcct();
    try {
        IGESControl_Writer writer("MM", 0);
        for (size_t i = 0; i < content.curves.size(); ++i) {
            if (!writer.AddGeom(toOcct(content.curves[i], indexed("curves", i)))) {
                throw ExchangeError(indexed("curves", i) + ": the IGES translator refused it");
            }
        }
        for (size_t i = 0; i < content.surfaces.size(); ++i) {
            if (!writer.AddGeom(toOcct(content.surfaces[i], indexed("surfaces", i)))) {
                throw ExchangeError(indexed("surfaces", i) + ": the IGES translator refused it");
            }
        }
        // As IGESControl_Writer::Write(stream), with full precision.
        writer.ComputeModel();
        IGESData_IGESWriter out(writer.Model());
        fullPrecision(out.FloatWriter());
        out.SendModel(IGESSelect_WorkLibrary::DefineProtocol());
        std::ostringstream text;
        if (!out.Print(text)) throw ExchangeError("path: the IGES writer failed");
        return text.str();
    } catch (const Standard_Failure& e) {
        throw ExchangeError(std::string("curves: OpenCASCADE failed (") + e.GetMessageString() + ")");
    }
}

}  // namespace sculptline::solvers::exchange
