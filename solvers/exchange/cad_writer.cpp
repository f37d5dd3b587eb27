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
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <unistd.h>

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

// STEPControl_Writer writes files only (no stream in 7.6): a private temporary file, read back.
std::string writeStepText(STEPControl_Writer& writer)
{
    std::string templ = (std::filesystem::temp_directory_path() / "sculptline-step-XXXXXX").string();
    const int fd = mkstemp(templ.data());
    if (fd < 0) throw ExchangeError("path: cannot create a temporary file for the STEP writer");
    close(fd);
    const IFSelect_ReturnStatus status = writer.Write(templ.c_str());
    std::ifstream in(templ, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    in.close();
    std::remove(templ.c_str());
    if (status != IFSelect_RetDone) throw ExchangeError("path: the STEP writer failed");
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
        return writeStepText(writer);
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
        writer.ComputeModel();
        std::ostringstream text;
        if (!writer.Write(text)) throw ExchangeError("path: the IGES writer failed");
        return text.str();
    } catch (const Standard_Failure& e) {
        throw ExchangeError(std::string("curves: OpenCASCADE failed (") + e.GetMessageString() + ")");
    }
}

}  // namespace sculptline::solvers::exchange
