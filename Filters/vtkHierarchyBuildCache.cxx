// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHierarchyBuildCache.h"

#include "LeafContentHash.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMFieldData.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <vtksys/SystemInformation.hxx>
#include <vtksys/SystemTools.hxx>

#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <list>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <utility>

vtkStandardNewMacro(vtkHierarchyBuildCache);

namespace
{
const char* const KeyArrayName = "TimeCriticalCacheKey";
const char* const HashArrayName = "TimeCriticalCacheContentHash";

std::string Hex(uint64_t value)
{
  std::ostringstream text;
  text << std::hex << std::setw(16) << std::setfill('0') << value;
  return text.str();
}

/// Collects the errors of the XML reader or writer, their executive and parser.
class MessageCollector : public vtkCommand
{
public:
  static MessageCollector* New() { return new MessageCollector; }
  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    if (event == vtkCommand::ErrorEvent && this->FirstError.empty())
    {
      this->FirstError = callData ? static_cast<const char*>(callData) : "error";
      std::string& text = this->FirstError;
      while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
      {
        text.pop_back();
      }
    }
    this->Failed = this->Failed || event == vtkCommand::ErrorEvent;
  }
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  std::string FirstError;
  bool Failed = false;
};

/// The cell array of `source`'s arrays (null stays null).
vtkSmartPointer<vtkCellArray> CellsSharingArrays(vtkCellArray* source)
{
  if (!source)
  {
    return nullptr;
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(source->GetOffsetsArray(), source->GetConnectivityArray());
  return cells;
}

/**
 * A new polydata that shares only the arrays of `source` (points, cells,
 * attributes), never a VTK object that threads could then use at once: the
 * points' cached bounds, a cell array's traversal position, cell links and
 * locators (which take part in VTK's garbage collection, not thread-safe).
 */
vtkSmartPointer<vtkPolyData> CopySharingArrays(vtkPolyData* source)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  if (source->GetPoints())
  {
    vtkNew<vtkPoints> points;
    points->SetData(source->GetPoints()->GetData());
    copy->SetPoints(points);
  }
  copy->SetVerts(CellsSharingArrays(source->GetVerts()));
  copy->SetLines(CellsSharingArrays(source->GetLines()));
  copy->SetPolys(CellsSharingArrays(source->GetPolys()));
  copy->SetStrips(CellsSharingArrays(source->GetStrips()));
  copy->GetPointData()->ShallowCopy(source->GetPointData());
  copy->GetCellData()->ShallowCopy(source->GetCellData());
  copy->GetFieldData()->ShallowCopy(source->GetFieldData());
  return copy;
}

/**
 * A new array over the values of `source` (numeric arrays: the same memory,
 * not copied), so that the writer's range computations, cached in the
 * array's information, never touch an array other threads use.
 */
vtkSmartPointer<vtkAbstractArray> ArrayView(vtkAbstractArray* source)
{
  vtkSmartPointer<vtkAbstractArray> view;
  view.TakeReference(source->NewInstance());
  auto* data = vtkDataArray::SafeDownCast(source);
  if (!data || !data->HasStandardMemoryLayout())
  {
    view->DeepCopy(source); // strings and the like: small, and rare in a hierarchy
    return view;
  }
  view->SetNumberOfComponents(source->GetNumberOfComponents());
  view->SetName(source->GetName());
  if (source->GetNumberOfValues() > 0)
  {
    view->SetVoidArray(data->GetVoidPointer(0), source->GetNumberOfValues(), 1);
  }
  return view;
}

/// The attribute arrays of `source` as views, with their active attributes.
void ViewAttributes(vtkDataSetAttributes* source, vtkDataSetAttributes* target)
{
  for (int i = 0; i < source->GetNumberOfArrays(); ++i)
  {
    target->AddArray(ArrayView(source->GetAbstractArray(i)));
  }
  for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
  {
    vtkAbstractArray* active = source->GetAbstractAttribute(attribute);
    if (active && active->GetName())
    {
      target->SetActiveAttribute(active->GetName(), attribute);
    }
  }
}

/// A polydata whose every array is a view of `source`'s (for the file writer).
vtkSmartPointer<vtkPolyData> ViewForWriting(vtkPolyData* source)
{
  auto view = vtkSmartPointer<vtkPolyData>::New();
  if (source->GetPoints())
  {
    vtkNew<vtkPoints> points;
    points->SetData(vtkDataArray::SafeDownCast(ArrayView(source->GetPoints()->GetData())));
    view->SetPoints(points);
  }
  vtkCellArray* sources[4] = { source->GetVerts(), source->GetLines(), source->GetPolys(),
    source->GetStrips() };
  vtkSmartPointer<vtkCellArray> cells[4];
  for (int i = 0; i < 4; ++i)
  {
    cells[i] = vtkSmartPointer<vtkCellArray>::New();
    if (sources[i])
    {
      cells[i]->SetData(vtkDataArray::SafeDownCast(ArrayView(sources[i]->GetOffsetsArray())),
        vtkDataArray::SafeDownCast(ArrayView(sources[i]->GetConnectivityArray())));
    }
  }
  view->SetVerts(cells[0]);
  view->SetLines(cells[1]);
  view->SetPolys(cells[2]);
  view->SetStrips(cells[3]);
  ViewAttributes(source->GetPointData(), view->GetPointData());
  ViewAttributes(source->GetCellData(), view->GetCellData());
  for (int i = 0; i < source->GetFieldData()->GetNumberOfArrays(); ++i)
  {
    view->GetFieldData()->AddArray(ArrayView(source->GetFieldData()->GetAbstractArray(i)));
  }
  return view;
}

/// A stored string of the file's field data ("" when missing).
std::string StoredText(vtkPolyData* data, const char* name)
{
  auto* array = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  return array && array->GetNumberOfValues() == 1 ? array->GetValue(0) : std::string();
}

/// Every attribute array has one tuple per point or cell.
std::string CheckAttributeSizes(vtkPolyData* data)
{
  const vtkIdType points = data->GetNumberOfPoints(), cells = data->GetNumberOfCells();
  for (int i = 0; i < data->GetPointData()->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = data->GetPointData()->GetAbstractArray(i);
    if (array->GetNumberOfTuples() != points)
    {
      return std::string("point-data array ") + (array->GetName() ? array->GetName() : "?") +
        " does not have one tuple per point";
    }
  }
  for (int i = 0; i < data->GetCellData()->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = data->GetCellData()->GetAbstractArray(i);
    if (array->GetNumberOfTuples() != cells)
    {
      return std::string("cell-data array ") + (array->GetName() ? array->GetName() : "?") +
        " does not have one tuple per cell";
    }
  }
  return std::string();
}

/**
 * Checks a file's data against the key it is read for and removes the
 * cache's own arrays; empty when it is the build of `key`, else the problem.
 */
std::string CheckEntry(vtkPolyData* data, const vtkHierarchyBuildCache::Key& key)
{
  const std::string storedKey = StoredText(data, KeyArrayName);
  const std::string storedHash = StoredText(data, HashArrayName);
  const std::string expected = vtkHierarchyBuildCache::KeyText(key);
  if (storedKey != expected)
  {
    return "foreign: it holds key '" + storedKey + "', not '" + expected + "'";
  }
  data->GetFieldData()->RemoveArray(KeyArrayName);
  data->GetFieldData()->RemoveArray(HashArrayName);
  if (storedHash != Hex(timecritical::HashLeafContent(data)))
  {
    return "damaged: its arrays do not match the content hash they were written with";
  }
  std::string problem = CheckAttributeSizes(data);
  if (!problem.empty())
  {
    return "damaged: " + problem;
  }
  if (key.Hierarchy == 1)
  {
    vtkNew<vtkMergeTreeFieldData> tree;
    if (!tree->Read(data))
    {
      return std::string("damaged: its merge tree is invalid: ") + tree->GetErrorMessage();
    }
  }
  else
  {
    vtkNew<vtkTOMFieldData> tom;
    if (!tom->Read(data))
    {
      return std::string("damaged: its TOM is invalid: ") + tom->GetErrorMessage();
    }
  }
  return std::string();
}

/// Reads and checks a cache file; null with `problem` set when unusable.
vtkSmartPointer<vtkPolyData> ReadEntry(
  const std::string& path, const vtkHierarchyBuildCache::Key& key, std::string& problem)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  vtkNew<MessageCollector> messages;
  messages->Watch(reader);
  messages->Watch(reader->GetExecutive());
  reader->SetReaderErrorObserver(messages);
  reader->SetParserErrorObserver(messages);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* read = reader->GetOutput();
  if (messages->Failed || !read || read->GetNumberOfPoints() == 0)
  {
    problem = "unreadable or truncated (" +
      (messages->FirstError.empty() ? std::string("no points") : messages->FirstError) + ")";
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> data = CopySharingArrays(read);
  // The reader names the cell arrays, which the builders leave unnamed (and
  // the content hash covers the names).
  for (vtkCellArray* cells :
    { data->GetVerts(), data->GetLines(), data->GetPolys(), data->GetStrips() })
  {
    if (cells)
    {
      cells->GetOffsetsArray()->SetName(nullptr);
      cells->GetConnectivityArray()->SetName(nullptr);
    }
  }
  problem = CheckEntry(data, key);
  return problem.empty() ? data : nullptr;
}

/// A name no other thread, process or host writes at the same time.
std::string TemporaryName(const std::string& path)
{
  static const uint64_t processToken = [] {
    std::random_device device;
    return (static_cast<uint64_t>(device()) << 32) ^ device() ^
      static_cast<uint64_t>(vtksys::SystemInformation().GetProcessId());
  }();
  static std::atomic<uint64_t> counter{ 0 };
  std::ostringstream name;
  name << path << "." << Hex(processToken) << "." << counter++ << ".tmp";
  return name.str();
}

/// A file can be made in `directory` (tried: permission bits do not tell for root).
bool CanWriteIn(const std::string& directory)
{
  const std::string probe = TemporaryName(directory + "/.write-test");
  bool written = false;
  {
    std::ofstream file(probe.c_str());
    written = static_cast<bool>(file << "x");
  }
  vtksys::SystemTools::RemoveFile(probe);
  return written;
}

/// Writes a build with its key, atomically; empty on success, else the problem.
std::string WriteEntry(
  const std::string& path, const vtkHierarchyBuildCache::Key& key, vtkPolyData* hierarchy)
{
  // Its own arrays: the cache's arrays stay off `hierarchy`, and no thread
  // sees the writer compute ranges.
  vtkSmartPointer<vtkPolyData> copy = ViewForWriting(hierarchy);
  const std::pair<const char*, std::string> stored[2] = {
    { KeyArrayName, vtkHierarchyBuildCache::KeyText(key) },
    { HashArrayName, Hex(timecritical::HashLeafContent(hierarchy)) }
  };
  for (const auto& entry : stored)
  {
    vtkNew<vtkStringArray> text;
    text->SetName(entry.first);
    text->InsertNextValue(entry.second);
    copy->GetFieldData()->AddArray(text);
  }
  const std::string temporary = TemporaryName(path);
  vtkNew<vtkXMLPolyDataWriter> writer;
  vtkNew<MessageCollector> messages;
  messages->Watch(writer);
  messages->Watch(writer->GetExecutive());
  writer->SetInputData(copy);
  writer->SetFileName(temporary.c_str());
  writer->SetDataModeToBinary(); // not appended: Debian's expat breaks VTK 9.2's appended reads
  writer->SetCompressorTypeToLZ4();
  writer->SetHeaderTypeToUInt64();
  if (!writer->Write() || messages->Failed)
  {
    vtksys::SystemTools::RemoveFile(temporary);
    return "could not be written (" + messages->FirstError + ")";
  }
  // Atomic where rename replaces (POSIX); elsewhere the old file goes first.
  if (std::rename(temporary.c_str(), path.c_str()) != 0 &&
    (std::remove(path.c_str()), std::rename(temporary.c_str(), path.c_str()) != 0))
  {
    vtksys::SystemTools::RemoveFile(temporary);
    return "could not be renamed from " + temporary;
  }
  return std::string();
}
} // namespace

//------------------------------------------------------------------------------
// The held objects are referenced only under the mutex (callers get copies):
// releasing one of several references to a vtkDataObject makes VTK's garbage
// collector walk that object, which must not race with its deletion by an
// eviction on another thread.
struct vtkHierarchyBuildCache::Internals
{
  struct Entry
  {
    Key EntryKey;
    vtkSmartPointer<vtkPolyData> Hierarchy;
    vtkTypeInt64 Bytes = 0;
  };
  std::mutex Mutex;
  std::list<Entry> Entries; // most recently used first
  std::map<Key, std::list<Entry>::iterator> Index;
  vtkTypeInt64 MemoryLimit = 0;
  vtkTypeInt64 MemoryInUse = 0;
  std::string Directory;
  vtkTypeInt64 MemoryHits = 0, DiskHits = 0, Misses = 0, Evictions = 0, RejectedFiles = 0,
               FilesWritten = 0;

  /// Evict the least recently used entries beyond the limit (Mutex held).
  void Trim()
  {
    while (this->MemoryInUse > this->MemoryLimit && !this->Entries.empty())
    {
      this->MemoryInUse -= this->Entries.back().Bytes;
      this->Index.erase(this->Entries.back().EntryKey);
      this->Entries.pop_back();
      ++this->Evictions;
    }
  }

  /// Keep `hierarchy` as the most recently used entry (Mutex held).
  void Put(const Key& key, vtkSmartPointer<vtkPolyData>&& hierarchy)
  {
    auto found = this->Index.find(key);
    if (found != this->Index.end())
    {
      this->MemoryInUse -= found->second->Bytes;
      this->Entries.erase(found->second);
      this->Index.erase(found);
    }
    Entry entry;
    entry.EntryKey = key;
    entry.Bytes = static_cast<vtkTypeInt64>(hierarchy->GetActualMemorySize()) * 1024;
    entry.Hierarchy = hierarchy;
    hierarchy = nullptr; // vtkSmartPointer has no move assignment: the caller's reference goes here
    this->MemoryInUse += entry.Bytes;
    this->Entries.push_front(std::move(entry));
    this->Index[key] = this->Entries.begin();
    this->Trim();
  }
};

//------------------------------------------------------------------------------
bool vtkHierarchyBuildCache::Key::operator<(const Key& other) const
{
  if (this->ContentHash != other.ContentHash)
  {
    return this->ContentHash < other.ContentHash;
  }
  if (this->Cells != other.Cells)
  {
    return this->Cells < other.Cells;
  }
  if (this->Hierarchy != other.Hierarchy)
  {
    return this->Hierarchy < other.Hierarchy;
  }
  return this->PairContractionDistance < other.PairContractionDistance;
}

vtkHierarchyBuildCache::vtkHierarchyBuildCache()
  : Internal(new Internals)
{
  this->Internal->MemoryLimit = GetDefaultMemoryLimit();
}

vtkHierarchyBuildCache::~vtkHierarchyBuildCache() = default;

vtkHierarchyBuildCache* vtkHierarchyBuildCache::GetSharedInstance()
{
  static vtkSmartPointer<vtkHierarchyBuildCache> shared =
    vtkSmartPointer<vtkHierarchyBuildCache>::New();
  return shared;
}

vtkTypeInt64 vtkHierarchyBuildCache::GetDefaultMemoryLimit()
{
  vtksys::SystemInformation system;
  system.RunMemoryCheck();
  const long long kib = system.GetHostMemoryTotal();
  return kib > 0 ? static_cast<vtkTypeInt64>(kib) * 1024 / 4 : vtkTypeInt64(1) << 30;
}

//------------------------------------------------------------------------------
void vtkHierarchyBuildCache::SetMemoryLimit(vtkTypeInt64 bytes)
{
  if (bytes < 0)
  {
    vtkErrorMacro("MemoryLimit must be >= 0 bytes (0 keeps nothing in memory), not "
      << bytes << "; it stays " << this->GetMemoryLimit() << ".");
    return;
  }
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  if (this->Internal->MemoryLimit != bytes)
  {
    this->Internal->MemoryLimit = bytes;
    this->Internal->Trim();
    this->Modified();
  }
}

vtkTypeInt64 vtkHierarchyBuildCache::GetMemoryLimit()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->MemoryLimit;
}

bool vtkHierarchyBuildCache::SetDirectory(const char* path)
{
  std::string directory = path ? path : "";
  std::string problem;
  if (!directory.empty())
  {
    directory = vtksys::SystemTools::CollapseFullPath(directory);
    if (!vtksys::SystemTools::FileIsDirectory(directory) &&
      !vtksys::SystemTools::MakeDirectory(directory).IsSuccess())
    {
      problem = "cannot be made";
    }
    else if (!CanWriteIn(directory))
    {
      problem = "is not writable";
    }
  }
  if (!problem.empty())
  {
    vtkErrorMacro("Hierarchy cache directory '" << directory << "' " << problem
                                                << ": the disk cache is off.");
    directory.clear();
  }
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  if (this->Internal->Directory != directory)
  {
    this->Internal->Directory = directory;
    this->Modified();
  }
  return problem.empty();
}

std::string vtkHierarchyBuildCache::GetDirectory()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  return this->Internal->Directory;
}

void vtkHierarchyBuildCache::Clear()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  this->Internal->Entries.clear();
  this->Internal->Index.clear();
  this->Internal->MemoryInUse = 0;
}

//------------------------------------------------------------------------------
#define vtkHierarchyBuildCacheStatistic(name, member)                                              \
  vtkTypeInt64 vtkHierarchyBuildCache::Get##name()                                                 \
  {                                                                                                \
    std::lock_guard<std::mutex> lock(this->Internal->Mutex);                                       \
    return static_cast<vtkTypeInt64>(this->Internal->member);                                      \
  }
vtkHierarchyBuildCacheStatistic(NumberOfMemoryHits, MemoryHits);
vtkHierarchyBuildCacheStatistic(NumberOfDiskHits, DiskHits);
vtkHierarchyBuildCacheStatistic(NumberOfMisses, Misses);
vtkHierarchyBuildCacheStatistic(NumberOfEvictions, Evictions);
vtkHierarchyBuildCacheStatistic(NumberOfRejectedFiles, RejectedFiles);
vtkHierarchyBuildCacheStatistic(NumberOfFilesWritten, FilesWritten);
vtkHierarchyBuildCacheStatistic(NumberOfEntries, Entries.size());
vtkHierarchyBuildCacheStatistic(MemoryInUse, MemoryInUse);
#undef vtkHierarchyBuildCacheStatistic

void vtkHierarchyBuildCache::ResetStatistics()
{
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  Internals& in = *this->Internal;
  in.MemoryHits = in.DiskHits = in.Misses = in.Evictions = in.RejectedFiles = in.FilesWritten = 0;
}

//------------------------------------------------------------------------------
vtkHierarchyBuildCache::Key vtkHierarchyBuildCache::MakeKey(
  vtkPolyData* leaf, int hierarchy, double pairContractionDistance)
{
  Key key;
  key.ContentHash = timecritical::HashLeafContent(leaf);
  key.Cells = leaf->GetNumberOfCells();
  key.Hierarchy = hierarchy;
  // vtkMergeTreeBuilder ignores the distance: its builds are the same.
  key.PairContractionDistance = hierarchy == 1 ? 0.0 : pairContractionDistance;
  return key;
}

std::string vtkHierarchyBuildCache::KeyText(const Key& key)
{
  std::ostringstream text;
  text << (key.Hierarchy == 1 ? "mergetree" : "tom") << "-" << Hex(key.ContentHash) << "-"
       << key.Cells << "-v" << static_cast<int>(FORMAT_VERSION);
  if (key.PairContractionDistance != 0.0)
  {
    uint64_t bits = 0; // exact, and a valid file name
    std::memcpy(&bits, &key.PairContractionDistance, sizeof(bits));
    text << "-pairs" << Hex(bits);
  }
  return text.str();
}

std::string vtkHierarchyBuildCache::FilePath(const Key& key)
{
  const std::string directory = this->GetDirectory();
  return directory.empty() ? directory : directory + "/" + KeyText(key) + ".vtp";
}

void vtkHierarchyBuildCache::Report(
  const std::string& warning, std::vector<std::string>* warnings)
{
  if (warnings)
  {
    warnings->push_back(warning);
  }
  else
  {
    vtkWarningMacro(<< warning);
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkHierarchyBuildCache::Find(
  const Key& key, std::vector<std::string>* warnings, bool* fromDisk)
{
  if (fromDisk)
  {
    *fromDisk = false;
  }
  std::string path;
  {
    std::lock_guard<std::mutex> lock(this->Internal->Mutex);
    auto found = this->Internal->Index.find(key);
    if (found != this->Internal->Index.end())
    {
      this->Internal->Entries.splice(
        this->Internal->Entries.begin(), this->Internal->Entries, found->second);
      ++this->Internal->MemoryHits;
      return CopySharingArrays(found->second->Hierarchy);
    }
    if (!this->Internal->Directory.empty())
    {
      path = this->Internal->Directory + "/" + KeyText(key) + ".vtp";
    }
  }
  std::string problem;
  vtkSmartPointer<vtkPolyData> read;
  if (!path.empty() && vtksys::SystemTools::FileExists(path, true))
  {
    read = ReadEntry(path, key, problem);
  }
  vtkSmartPointer<vtkPolyData> copy; // not the object the cache holds
  if (read)
  {
    copy = CopySharingArrays(read);
  }
  {
    std::lock_guard<std::mutex> lock(this->Internal->Mutex);
    this->Internal->RejectedFiles += problem.empty() ? 0 : 1;
    ++(read ? this->Internal->DiskHits : this->Internal->Misses);
    if (read)
    {
      this->Internal->Put(key, std::move(read)); // no reference left outside the lock
    }
  }
  if (!problem.empty())
  {
    this->Report("Hierarchy cache file " + path + " is " + problem +
        ": ignored; the leaf is built again and the file rewritten.",
      warnings);
  }
  if (fromDisk)
  {
    *fromDisk = copy != nullptr;
  }
  return copy;
}

void vtkHierarchyBuildCache::Insert(
  const Key& key, vtkPolyData* hierarchy, std::vector<std::string>* warnings)
{
  if (!hierarchy)
  {
    return;
  }
  vtkSmartPointer<vtkPolyData> stored = CopySharingArrays(hierarchy);
  std::string directory;
  {
    std::lock_guard<std::mutex> lock(this->Internal->Mutex);
    this->Internal->Put(key, std::move(stored)); // no reference left outside the lock
    directory = this->Internal->Directory;
  }
  if (directory.empty())
  {
    return;
  }
  const std::string path = directory + "/" + KeyText(key) + ".vtp";
  const std::string problem = WriteEntry(path, key, hierarchy);
  if (!problem.empty())
  {
    this->Report("Hierarchy cache file " + path + " " + problem + ".", warnings);
    return;
  }
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  ++this->Internal->FilesWritten;
}

//------------------------------------------------------------------------------
void vtkHierarchyBuildCache::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  std::lock_guard<std::mutex> lock(this->Internal->Mutex);
  const Internals& in = *this->Internal;
  os << indent << "MemoryLimit: " << in.MemoryLimit << "\n";
  os << indent << "MemoryInUse: " << in.MemoryInUse << "\n";
  os << indent << "Entries: " << in.Entries.size() << "\n";
  os << indent << "Directory: " << in.Directory << "\n";
  os << indent << "MemoryHits: " << in.MemoryHits << ", DiskHits: " << in.DiskHits
     << ", Misses: " << in.Misses << ", Evictions: " << in.Evictions
     << ", RejectedFiles: " << in.RejectedFiles << ", FilesWritten: " << in.FilesWritten << "\n";
}
